// The retina stage of the eye simulator: per-cone bleaching and calcium
// state on a retina-fixed grid, stepped through each frame's gaze segments,
// and the afterimages it adds to the display (seed 001 sec. 2.2).
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pipeline/gaze_timeline.hpp"
#include "pipeline/plan.hpp"
#include "retina/retina_state.hpp"
#include "retina/retinal_grid.hpp"

namespace eyestream::pipeline {

class RetinaStage {
 public:
  explicit RetinaStage(const Plan& plan);

  // Steps the state through `segments` (one frame interval) with the scene
  // `rgb` (cd/m^2); `adaptation_log[i]` is the global adaptation after
  // segment i. Consecutive segments with the same eye state and a gaze
  // within the plan's sub-step tolerance are stepped together. The first
  // call starts the retina at rest for its first stimulus.
  void advance(const cv::Mat& rgb, const std::vector<GazeSegment>& segments, const std::vector<double>& adaptation_log);

  // Adds the afterimages at the gaze (x, y) to the tone-mapped frame.
  void composite(const cv::Mat& tone_mapped, double gaze_x, double gaze_y, cv::Mat& out) const;

  // Writes B and C per cone (channels B.L, B.M, B.S, C.L, C.M, C.S) of the
  // grid as a float EXR.
  void write_state(const std::string& path) const;

  const retina::RetinaState& state() const { return state_; }
  // Checkpoints: the state's matrices, and whether it has started.
  std::vector<cv::Mat> save(bool& started) const {
    started = started_;
    return state_.save();
  }
  void restore(const std::vector<cv::Mat>& mats, bool started) {
    state_.restore(mats);
    started_ = started;
  }
  const retina::RetinalGrid& grid() const { return grid_; }

 private:
  const Plan plan_;
  retina::RetinalGrid grid_;
  retina::RetinaState state_;
  cv::Mat visibility_;  // foveal fall-off of afterimages on the grid
  cv::Mat dark_;
  bool started_ = false;
};

}  // namespace eyestream::pipeline
