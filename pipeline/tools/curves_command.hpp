// `eyestream curves`: a picture of the tone-curve family (docs/model.md asks
// for one), drawn with OpenCV.
#pragma once

#include <string>

#include "retina/tone_curve.hpp"

namespace eyestream::pipeline {

// Draws R(I) against log10 I from -6 to 8 for adaptation levels A = -4,
// -2, 0, 2, 4 and 6, each marked where it meets its plateau M(A), and M
// itself as a dashed curve; writes a PNG (staged).
void write_tone_curves(const retina::ToneCurveParams& tone, const std::string& path);

}  // namespace eyestream::pipeline
