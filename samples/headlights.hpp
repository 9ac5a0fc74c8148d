// The `headlights` scene: a still night view of an oncoming car's
// headlights with a dim pedestrian target a few degrees beside them, the
// gaze on the target (Spencer et al. 1995, Yoshida et al. 2008: glare and visibility).
#pragma once

#include <opencv2/core.hpp>

#include "samples/scene.hpp"

namespace eyestream::samples {

inline constexpr double kHeadlightsDuration_s = 3.0;
inline constexpr double kHeadlightsLuminance = 1e5;  // cd/m^2 of each lamp
inline constexpr double kHeadlightsRoad = 0.3;       // cd/m^2 background
inline constexpr double kHeadlightsTarget = 0.6;     // cd/m^2 of the pedestrian
inline constexpr double kHeadlightsSpacing_deg = 1.4, kHeadlightsRadius_deg = 0.08;
inline constexpr double kHeadlightsTargetOffset_deg = 4.0;  // target centre, left of the lamps

// The target's rectangle (0.3 x 1 deg) in a frame of this size under the
// default viewing condition.
cv::Rect headlights_target(cv::Size frame);

void generate_headlights(const SceneOptions& options);

}  // namespace eyestream::samples
