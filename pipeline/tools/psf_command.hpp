// `eyestream psf`: the viewer's point-spread function as the glare stage
// uses it, for inspection.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "pipeline/settings/settings.hpp"

namespace eyestream::pipeline {

struct PsfRequest {
  int width = 640, height = 360;  // the frame the kernel is for
  double adaptation_log = 1.0;    // log10 cd/m^2 the viewer is adapted to
  std::string output;             // kernel.exr; a log-scale picture goes beside it as .png
};

struct PsfSummary {
  double pupil_mm = 0;
  double within[3] = {0, 0, 0};  // energy within 0.05, 1 and 10 deg (green channel)
  std::string text() const;
};

// The kernel for `settings` (viewer, viewing condition) and a width x
// height frame, adapted to 10^adaptation_log cd/m^2: R, G, B (CV_32FC3),
// (2W-1) x (2H-1), its centre at (W-1, H-1), each channel's sum the share
// of a pixel's light the glare spreads over the frame's reach.
struct ViewerPsf {
  cv::Mat kernel;
  double pixels_per_degree = 0;
  PsfSummary summary;
};
ViewerPsf viewer_psf(const Settings& settings, int width, int height, double adaptation_log);

// Builds the kernel for `settings` (viewer, viewing condition) and writes
// it as a float EXR (R, G, B; (2W-1) x (2H-1), centred) and a PNG of
// log10(K / K_max) from -8 (black) to 0 (white), per channel.
PsfSummary write_psf(const Settings& settings, const PsfRequest& request);

}  // namespace eyestream::pipeline
