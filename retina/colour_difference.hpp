// Colour difference for comparing outputs: CIELAB from display-linear
// Rec.709 and the CIEDE2000 difference (Sharma, Wu and Dalal 2005, "The
// CIEDE2000 color-difference formula: implementation notes"; CIE 142:2001).
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::retina {

// CIELAB (L*, a*, b*) of a linear Rec.709 colour relative to a display white
// of 1 (D65 white point, IEC 61966-2-1 matrix).
cv::Vec3d lab_from_linear_rec709(const cv::Vec3f& rgb);

// CIEDE2000 Delta E_00 between two CIELAB colours (k_L = k_C = k_H = 1).
double ciede2000(const cv::Vec3d& lab1, const cv::Vec3d& lab2);

}  // namespace eyestream::retina
