// The `night-drive` scene.
#pragma once

#include "samples/scene.hpp"

namespace eyestream::samples {

inline constexpr double kNightDriveDuration_s = 6.0;

void generate_night_drive(const SceneOptions& options);

}  // namespace eyestream::samples
