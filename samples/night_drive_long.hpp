// The `night-drive-long` scene: twenty seconds on the night road
// (night_road.hpp) with an approaching car and a pedestrian at the road
// edge, the driver's gaze moving between the road, the pedestrian and the
// headlights, with blinks; the pedestrian's mask is the visibility target.
#pragma once

#include "samples/scene.hpp"

namespace eyestream::samples {

inline constexpr double kNightDriveLongDuration_s = 20.0;

void generate_night_drive_long(const SceneOptions& options);

}  // namespace eyestream::samples
