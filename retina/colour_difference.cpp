#include "retina/colour_difference.hpp"

#include <algorithm>
#include <cmath>

namespace eyestream::retina {

namespace {

constexpr double kDeg = M_PI / 180.0;

double lab_f(double t) {
  constexpr double d = 6.0 / 29.0;
  return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29.0;
}

// Hue angle in degrees, [0, 360); 0 for the neutral axis.
double hue(double b, double a) {
  if (a == 0 && b == 0) return 0.0;
  const double h = std::atan2(b, a) / kDeg;
  return h < 0 ? h + 360.0 : h;
}

}  // namespace

cv::Vec3d lab_from_linear_rec709(const cv::Vec3f& c) {
  const double r = c[0], g = c[1], b = c[2];
  const double x = 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
  const double y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
  const double z = 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
  const double fx = lab_f(x / 0.95047), fy = lab_f(y), fz = lab_f(z / 1.08883);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

// Sharma et al. 2005, eqs. (2)-(22).
double ciede2000(const cv::Vec3d& lab1, const cv::Vec3d& lab2) {
  const double L1 = lab1[0], a1 = lab1[1], b1 = lab1[2], L2 = lab2[0], a2 = lab2[1], b2 = lab2[2];
  const double c_bar = (std::hypot(a1, b1) + std::hypot(a2, b2)) / 2;
  const double c7 = std::pow(c_bar, 7), p25 = std::pow(25.0, 7);
  const double g = 0.5 * (1 - std::sqrt(c7 / (c7 + p25)));
  const double a1p = (1 + g) * a1, a2p = (1 + g) * a2;
  const double c1p = std::hypot(a1p, b1), c2p = std::hypot(a2p, b2);
  const double h1p = hue(b1, a1p), h2p = hue(b2, a2p);
  const double dLp = L2 - L1, dCp = c2p - c1p;
  double dhp = 0.0;
  if (c1p * c2p != 0) {
    dhp = h2p - h1p;
    if (dhp > 180) dhp -= 360;
    else if (dhp < -180) dhp += 360;
  }
  const double dHp = 2 * std::sqrt(c1p * c2p) * std::sin(dhp / 2 * kDeg);
  const double L_bar = (L1 + L2) / 2, cp_bar = (c1p + c2p) / 2;
  double hp_bar = h1p + h2p;
  if (c1p * c2p != 0) {
    if (std::abs(h1p - h2p) <= 180) hp_bar /= 2;
    else hp_bar = hp_bar < 360 ? (hp_bar + 360) / 2 : (hp_bar - 360) / 2;
  }
  const double t = 1 - 0.17 * std::cos((hp_bar - 30) * kDeg) + 0.24 * std::cos(2 * hp_bar * kDeg) +
                   0.32 * std::cos((3 * hp_bar + 6) * kDeg) - 0.20 * std::cos((4 * hp_bar - 63) * kDeg);
  const double d_theta = 30 * std::exp(-std::pow((hp_bar - 275) / 25, 2));
  const double cp7 = std::pow(cp_bar, 7);
  const double r_c = 2 * std::sqrt(cp7 / (cp7 + p25));
  const double l50 = (L_bar - 50) * (L_bar - 50);
  const double s_l = 1 + 0.015 * l50 / std::sqrt(20 + l50), s_c = 1 + 0.045 * cp_bar, s_h = 1 + 0.015 * cp_bar * t;
  const double r_t = -std::sin(2 * d_theta * kDeg) * r_c;
  const double l = dLp / s_l, c = dCp / s_c, h = dHp / s_h;
  return std::sqrt(l * l + c * c + h * h + r_t * c * h);
}

cv::Mat ciede2000_map(const cv::Mat& a, const cv::Mat& b, double decode_gamma) {
  CV_Assert(a.size() == b.size() && a.type() == CV_32FC3 && b.type() == CV_32FC3);
  auto linear = [decode_gamma](const cv::Vec3f& v) {
    if (decode_gamma == 1.0) return v;
    cv::Vec3f out;
    for (int c = 0; c < 3; ++c) out[c] = float(std::pow(std::max(v[c], 0.0f), decode_gamma));
    return out;
  };
  cv::Mat de(a.size(), CV_32F);
  cv::parallel_for_(cv::Range(0, a.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const cv::Vec3f* pa = a.ptr<cv::Vec3f>(y);
      const cv::Vec3f* pb = b.ptr<cv::Vec3f>(y);
      float* out = de.ptr<float>(y);
      for (int x = 0; x < a.cols; ++x)
        out[x] = float(ciede2000(lab_from_linear_rec709(linear(pa[x])), lab_from_linear_rec709(linear(pb[x]))));
    }
  });
  return de;
}

void DeltaEHistogram::add(const cv::Mat& de) {
  CV_Assert(de.type() == CV_32F);
  for (auto it = de.begin<float>(); it != de.end<float>(); ++it) {
    ++bins_[std::min(bins_.size() - 1, size_t(std::max(*it, 0.0f) / kStep))];
    max_ = std::max(max_, double(*it));
  }
  count_ += de.total();
}

double DeltaEHistogram::quantile(double q) const {
  const std::uint64_t target = std::uint64_t(std::ceil(q * double(count_)));
  std::uint64_t seen = 0;
  for (size_t i = 0; i < bins_.size() && count_ > 0; ++i)
    if ((seen += bins_[i]) >= target) return double(i) * kStep;
  return 0.0;
}

}  // namespace eyestream::retina
