// The `night-city` scene: a city street at night seen from the pavement,
// with far more light above a display's peak than the night road: lit
// windows on dark facades, neon signs, sodium and LED street lamps, traffic
// signals, and cars whose headlights and tail lights cross the view; the
// gaze wanders across it in fixations and saccades, with a blink. Real
// captures of such streets are what the bench must not flatter the presets
// on (most of the glare engine's work is spread from many lights).
#pragma once

#include "samples/scene.hpp"

namespace eyestream::samples {

inline constexpr double kNightCityDuration_s = 6.0;

void generate_night_city(const SceneOptions& options);

}  // namespace eyestream::samples
