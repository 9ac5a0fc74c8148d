// The gaze over time as piecewise-constant segments, cut at every gaze
// sample, so the eye model can sub-step inside a frame interval (docs/model.md).
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include "io/gaze_sample.hpp"

namespace eyestream::pipeline {

struct GazeSegment {
  double t0_s = 0.0, t1_s = 0.0;  // [t0, t1)
  double x = 0.0, y = 0.0;        // frame pixels
  bool eye_closed = false;        // blink: the eye sees darkness
  // The recorded pupil of the interval segments() was asked for (mm;
  // recorded_pupil_mm()), NaN when the log records none.
  double recorded_pupil_mm = std::numeric_limits<double>::quiet_NaN();
  double duration() const { return t1_s - t0_s; }
};

class GazeTimeline {
 public:
  // No samples: a fixed gaze at (default_x, default_y), eyes open. Lost
  // samples hold the last known position (eyes open); blinks keep the last
  // position with eyes closed. Before the first sample the first one holds.
  GazeTimeline(const std::vector<io::GazeSample>& samples, double default_x, double default_y);

  // Segments covering [t0, t1), cut at the sample times inside it. An empty
  // interval (t1 <= t0) gives one segment of zero length at t0.
  std::vector<GazeSegment> segments(double t0_s, double t1_s) const;

  // The pupil diameter the tracker recorded over [t0, t1) (mm): the mean of
  // the open-eye samples inside with a diameter; across a blink, lost
  // samples or a gap, the diameter interpolated at the interval's middle
  // between the nearest such samples before and after (the nearest one
  // when there is only one side); none when no sample has a diameter.
  std::optional<double> recorded_pupil_mm(double t0_s, double t1_s) const;

 private:
  struct Held {
    double t_s, x, y;
    bool closed;
  };
  std::vector<Held> held_;
  struct Pupil {
    double t_s, mm;
  };
  std::vector<Pupil> pupils_;  // open-eye samples with a recorded diameter
};

}  // namespace eyestream::pipeline
