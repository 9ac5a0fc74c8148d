// Every panel's eye (viewer_panels.hpp; an eyestream::Eye of the library
// API) over the same input, composed into one display frame (preview.hpp)
// and encoded for the sink.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "io/frame_sink.hpp"
#include "io/frame_source.hpp"
#include "io/gaze_sample.hpp"
#include "pipeline/api/eye_access.hpp"
#include "pipeline/preview/preview.hpp"
#include "pipeline/preview/viewer_panels.hpp"

namespace eyestream::pipeline {

class PreviewRenderer {
 public:
  PreviewRenderer(const Settings& settings, const io::SourceInfo& source, io::SinkNeeds needs);

  // Every eye takes its gaze from the whole recording (none: the frame's
  // centre), as eyestream::Eye::set_gaze.
  void set_gaze(const std::vector<io::GazeSample>& recording);
  // Steps every panel's eye through the frame's interval [frame.time_s,
  // t1_s) and returns the composed frame, encoded when the sink needs
  // codes. report(i) then holds panel i's FrameReport. The last panel's
  // eye is handed the frame itself (EyeSimulator::process).
  io::DisplayFrame process(io::SceneFrame frame, double t1_s);

  size_t panels() const { return panels_.size(); }
  const PanelSpec& spec(size_t i) const { return panels_[i].spec; }
  const FrameReport& report(size_t i) const { return detail::EyeAccess::report(panels_[i].eye); }
  const Plan& plan(size_t i) const { return detail::EyeAccess::plan(panels_[i].eye); }
  const EyeSimulator& eye(size_t i) const { return detail::EyeAccess::simulator(panels_[i].eye); }
  // Checkpoints: every panel's memory, and back.
  std::vector<EyeMemory> save() const;
  void restore(const std::vector<EyeMemory>& memories);
  // What is wrong with `memories` for these panels (empty: nothing).
  std::string memory_error(const std::vector<EyeMemory>& memories) const;
  // The first viewer panel (the one logs and --state-exr follow).
  size_t main_panel() const;
  // Each panel's plan, headed by its label when there are several.
  std::string describe() const;

 private:
  struct Panel {
    PanelSpec spec;
    Eye eye;
  };
  std::vector<Panel> panels_;
  PreviewOptions options_;
  io::SinkNeeds needs_;
};

}  // namespace eyestream::pipeline
