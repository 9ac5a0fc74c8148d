// The preview frame: the panels side by side with labels, gaze markers and
// a timecode burned in on request, in display-linear values (1 = display
// white) before encoding, so every output kind shows them alike.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace eyestream::pipeline {

struct PanelView {
  cv::Mat linear;  // CV_32FC3, every panel the same size
  std::string label;
  double gaze_x = 0.0, gaze_y = 0.0;  // frame pixels
  bool eye_closed = false;
};

struct PreviewOptions {
  bool labels = false;
  bool gaze = false;
  bool timecode = false;
  double marker_radius_px = 10.0;  // gaze marker ring
};

// Panels left to right. One panel and no overlay: that panel's frame
// itself (no copy). Deterministic: the same inputs give the same pixels.
cv::Mat compose_preview(const std::vector<PanelView>& panels, const PreviewOptions& options, double time_s,
                        std::int64_t frame_index);

}  // namespace eyestream::pipeline
