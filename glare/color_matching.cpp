#include "glare/color_matching.hpp"

#include <algorithm>
#include <cmath>

namespace eyestream::glare {

namespace {

// Piecewise Gaussian: width s1 below the mean, s2 above.
double lobe(double x, double mean, double s1, double s2) {
  const double t = (x - mean) / (x < mean ? s1 : s2);
  return std::exp(-0.5 * t * t);
}

}  // namespace

cv::Vec3d cie1931_xyz(double l) {
  const double x =
      1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) - 0.065 * lobe(l, 501.1, 20.4, 26.2);
  const double y = 0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1);
  const double z = 1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8);
  return {x, y, z};
}

cv::Vec3d rec709_rgb_sensitivity(double l) {
  const cv::Matx33d xyz_to_rgb(3.2404542, -1.5371385, -0.4985314, -0.9692660, 1.8760108, 0.0415560, 0.0556434,
                               -0.2040259, 1.0572252);  // IEC 61966-2-1
  const cv::Vec3d rgb = xyz_to_rgb * cie1931_xyz(l);
  return {std::max(rgb[0], 0.0), std::max(rgb[1], 0.0), std::max(rgb[2], 0.0)};
}

}  // namespace eyestream::glare
