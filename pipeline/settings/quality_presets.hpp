// Named quality presets: documented bundles of individual settings, in the
// manner of OpenColorIO's optimisation levels. Every knob of a preset can
// still be set on its own, and an explicit value wins over the preset.
#pragma once

#include <string>

#include "pipeline/settings/settings.hpp"

namespace eyestream::pipeline {

// reference: double-precision retina state at one site per pixel, a state
//   step at every gaze sample, the exact Vos FFT glare, every acuity blur at
//   full resolution. The yardstick.
// balanced (default): float state at 0.25 sites per pixel raised to 20
//   per degree up to 0.5 (0.31 per pixel at 1080p), gaze samples
//   within 0.05 deg share a step, the split glare engine with its tail at
//   half resolution, acuity blurs from 2.5 px wide at reduced resolution.
// fast: float state at 0.25 sites per pixel, samples within 0.25 deg share
//   a step, the split engine with its tail at quarter resolution, acuity
//   blurs from 1.2 px wide at reduced resolution.
// Every preset skips work a frame does not need (stage_activity.hpp).
// UsageError for another name.
// Documented error bounds against reference: the 99th percentile of
// CIEDE2000 over every pixel of every frame of the built-in scenes
// (tests/quality_presets_test.cpp; `eyestream bench` measures it at 720p
// and 1080p).
inline constexpr double kBalancedDe2000P99 = 1.5;
inline constexpr double kFastDe2000P99 = 3.0;

void apply_quality_preset(const std::string& name, Settings& s);

}  // namespace eyestream::pipeline
