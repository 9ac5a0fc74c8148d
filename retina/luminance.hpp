// Luminance of linear Rec.709 RGB.
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::retina {

// Photopic luminance weights of Rec.709 RGB (Jacobs et al. 2015 App. A wP).
inline constexpr float kPhotopicR = 0.2126f, kPhotopicG = 0.7152f, kPhotopicB = 0.0722f;

inline float photopic_luminance(const cv::Vec3f& rgb) {
  return kPhotopicR * rgb[0] + kPhotopicG * rgb[1] + kPhotopicB * rgb[2];
}

// The photopic luminance of each pixel of `rgb` (CV_32FC3) as CV_32F, with
// luminance below floor_cd_m2, and non-finite luminance, set to the floor.
cv::Mat floored_luminance(const cv::Mat& rgb, double floor_cd_m2);
// The same for one row of n interleaved RGB pixels, into out[0, n).
void floored_luminance_row(const float* rgb, float floor_cd_m2, float* out, int n);

}  // namespace eyestream::retina
