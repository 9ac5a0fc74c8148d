// Named quality presets: documented bundles of individual settings, in the
// manner of OpenColorIO's optimisation levels. Every knob of a preset can
// still be set on its own, and an explicit value wins over the preset.
#pragma once

#include <string>

#include "pipeline/settings.hpp"

namespace eyestream::pipeline {

// reference: double-precision retina state at one site per pixel, a state
//   step at every gaze sample, the exact Vos FFT glare.
// balanced (default): float state at 0.5 sites per pixel, gaze samples
//   within 0.05 deg share a step, the exact Vos FFT glare.
// fast: float state at 0.25 sites per pixel, samples within 0.25 deg share
//   a step, seed 003's Gaussian glare kernel.
// UsageError for another name.
void apply_quality_preset(const std::string& name, Settings& s);

}  // namespace eyestream::pipeline
