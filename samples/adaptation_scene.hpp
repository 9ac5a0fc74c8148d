// The `adaptation` scene: a long fixation between a bright white patch and
// a saturated blue patch on grey, then uniform grey (Jacobs et al. 2015 fig. 9).
#pragma once

#include "samples/scene.hpp"

namespace eyestream::samples {

inline constexpr double kAdaptationDuration_s = 15.0;
inline constexpr double kAdaptationSwitch_s = 10.0;  // the patches vanish
inline constexpr double kAdaptationGrey = 100.0;     // cd/m^2
inline constexpr double kAdaptationWhite = 1000.0;   // cd/m^2

// Patch centres and half size as fractions of the frame width/height.
inline constexpr double kWhitePatchX = 0.3, kBluePatchX = 0.7, kPatchY = 0.5, kPatchHalf = 0.1;

void generate_adaptation(const SceneOptions& options);

}  // namespace eyestream::samples
