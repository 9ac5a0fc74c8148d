// A gaze log for scenes viewed with a steady gaze.
#pragma once

#include <vector>

#include "io/gaze_sample.hpp"

namespace eyestream::samples {

// Samples at `rate_hz` over [0, duration_s) fixating (x, y).
std::vector<io::GazeSample> fixed_gaze(double x, double y, double duration_s, double rate_hz);

}  // namespace eyestream::samples
