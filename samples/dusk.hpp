// The `dusk` scene: a colour checker and a resolution target under light
// fading from daylight to deep mesopic and back (Jacobs et al. 2015 figs. 11-12).
#pragma once

#include <opencv2/core.hpp>

#include "samples/scene.hpp"

namespace eyestream::samples {

inline constexpr double kDuskDuration_s = 24.0;
inline constexpr double kDuskBrightWhite = 1e3;  // cd/m^2 of a perfect white at the start and end
inline constexpr double kDuskDarkWhite = 1e-2;   // cd/m^2 at the middle

// Luminance (cd/m^2) of a perfect white at time t: log-linear down over the
// first half, back up over the second.
double dusk_white(double t_s, double duration_s, double bright = kDuskBrightWhite);

// Where things are, as fractions of the frame: the checker's 6x4 patches
// and the target's bar groups.
cv::Rect dusk_checker_patch(int index, cv::Size frame);
cv::Rect dusk_target(cv::Size frame);

// The scene's reflectance map (linear Rec.709, a perfect white = 1).
cv::Mat dusk_reflectance(cv::Size frame);

void generate_dusk(const SceneOptions& options);

}  // namespace eyestream::samples
