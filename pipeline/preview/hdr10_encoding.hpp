// HDR10 encoding of the simulated view: display-linear J (1 = the display
// peak, --display-peak) to absolute luminance, Rec.709 to BT.2020 linear,
// then SMPTE ST 2084 (PQ) code values, for HDR displays.
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::pipeline {

// `linear` CV_32FC3 display-linear Rec.709; `code` CV_16UC3 PQ BT.2020 at
// full 16-bit scale (the writer keeps 10 bits). Negative (out-of-BT.2020)
// and non-finite values encode as 0; no dithering (10-bit PQ steps are
// below visibility).
void encode_hdr10(const cv::Mat& linear, double display_peak_cd_m2, cv::Mat& code);

}  // namespace eyestream::pipeline
