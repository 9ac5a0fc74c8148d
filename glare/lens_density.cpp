#include "glare/lens_density.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "glare/color_matching.hpp"

namespace eyestream::glare {

namespace {

// Pokorny, Smith and Lutze 1987, Table I: TL1 (the part that grows with
// age) and TL2 (the constant part), 400 to 650 nm every 10 nm.
constexpr std::array<double, 26> kTL1 = {0.600, 0.510, 0.433, 0.377, 0.327, 0.295, 0.267, 0.233, 0.207,
                                         0.187, 0.167, 0.147, 0.133, 0.120, 0.107, 0.093, 0.080, 0.067,
                                         0.053, 0.040, 0.033, 0.027, 0.020, 0.013, 0.007, 0.000};
constexpr std::array<double, 26> kTL2 = {1.000, 0.583, 0.300, 0.116, 0.033, 0.005, 0, 0, 0, 0, 0, 0, 0,
                                         0,     0,     0,     0,     0,     0,     0, 0, 0, 0, 0, 0, 0};

double table(const std::array<double, 26>& t, double lambda_nm) {
  const double i = std::clamp((lambda_nm - 400.0) / 10.0, 0.0, 25.0);
  const int lo = std::min(int(i), 24);
  return t[size_t(lo)] + (i - lo) * (t[size_t(lo) + 1] - t[size_t(lo)]);
}

}  // namespace

double lens_density(double lambda_nm, double age_years) {
  const double a = std::max(age_years, 20.0);
  const double growth = a <= 60.0 ? 1.0 + 0.02 * (a - 32.0) : 1.56 + 0.0667 * (a - 60.0);
  return table(kTL1, lambda_nm) * growth + table(kTL2, lambda_nm);
}

cv::Matx33f lens_filter_rgb(double age_years) {
  cv::Matx33d filtered = cv::Matx33d::zeros(), plain = cv::Matx33d::zeros();
  for (double l = 380.0; l <= 780.0; l += 1.0) {
    const cv::Vec3d s = rec709_rgb_sensitivity(l);
    const double t = std::pow(10.0, -(lens_density(l, age_years) - lens_density(l, 32.0)));
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) {
        filtered(k, c) += s[k] * s[c] * t;
        plain(k, c) += s[k] * s[c];
      }
  }
  // Channel c's light, seen through the lens, as the display's channels:
  // the projection of s_c T onto the s_k, relative to s_c's own.
  const cv::Matx33d m = plain.inv() * filtered;
  return cv::Matx33f(m);
}

}  // namespace eyestream::glare
