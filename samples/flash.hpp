// The `flash` scene: a camera-flash-like neutral disk for 1/8 s on black,
// then darkness, gaze fixed on it (Jacobs et al. 2015 figs. 4-5).
#pragma once

#include "samples/scene.hpp"

namespace eyestream::samples {

inline constexpr double kFlashDuration_s = 5.0;
inline constexpr double kFlashLuminance = 1e7;  // cd/m^2, Jacobs et al. 2015 fig. 4
inline constexpr double kFlashStart_s = 0.5, kFlashLength_s = 0.125;
inline constexpr double kFlashRadius_deg = 2.0;

void generate_flash(const SceneOptions& options);

}  // namespace eyestream::samples
