// Applies the tone curve to a frame, keeping colour ratios (Jacobs et al. 2015 sec.
// 2.1: "enforcing a consistent ratio between color channels").
#pragma once

#include <opencv2/core.hpp>

#include "retina/mesopic.hpp"
#include "retina/tone_curve.hpp"

namespace eyestream::retina {

// display_linear = R(Y) * rgb / Y per pixel, Y the photopic luminance of
// `rgb` (CV_32FC3, cd/m^2). Pixels with Y <= 0 or non-finite values map to
// black. Channels may exceed 1 or be negative (saturated or out-of-gamut
// colours); display encoding clips them. Threads over rows; the result does
// not depend on the thread count.
void tone_map(const cv::Mat& rgb, const ToneCurve& curve, cv::Mat& display_linear);

// Mesopic tone mapping (Jacobs et al. 2015 secs. 2.3.1-2.3.2): the curve is applied to
// the mesopic luminance Ym = rho Yp + (1 - rho) Ys (Purkinje shift), and
// colour is rebuilt from rho rgb / Yp + (1 - rho) tint_ratio (hue shift and
// desaturation toward the scotopic grey). The output's photopic luminance
// is R(Ym), so at equal photopic luminance blue gains on red as rho falls.
// With mesopic.rho_map set, rho is taken per pixel (local mesopic colour).
void tone_map(const cv::Mat& rgb, const ToneCurve& curve, const MesopicColour& mesopic, cv::Mat& display_linear);

}  // namespace eyestream::retina
