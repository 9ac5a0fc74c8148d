// The gaze over time as piecewise-constant segments, cut at every gaze
// sample, so the eye model can sub-step inside a frame interval (docs/model.md).
#pragma once

#include <vector>

#include "io/gaze_sample.hpp"

namespace eyestream::pipeline {

struct GazeSegment {
  double t0_s = 0.0, t1_s = 0.0;  // [t0, t1)
  double x = 0.0, y = 0.0;        // frame pixels
  bool eye_closed = false;        // blink: the eye sees darkness
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

 private:
  struct Held {
    double t_s, x, y;
    bool closed;
  };
  std::vector<Held> held_;
};

}  // namespace eyestream::pipeline
