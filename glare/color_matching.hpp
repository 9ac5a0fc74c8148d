// CIE 1931 2-degree colour-matching functions, from the multi-lobe
// Gaussian fit of Wyman, Sloan and Shirley (2013, "Simple analytic
// approximations to the CIE XYZ color matching functions", JCGT 2(2)),
// accurate to about 1 % of the peak.
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::glare {

// (x-bar, y-bar, z-bar) at wavelength lambda (nm).
cv::Vec3d cie1931_xyz(double lambda_nm);

// Linear Rec.709 RGB colour-matching functions, negative lobes set to 0:
// the weight of wavelength lambda in each display channel.
cv::Vec3d rec709_rgb_sensitivity(double lambda_nm);

}  // namespace eyestream::glare
