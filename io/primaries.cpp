#include "io/primaries.hpp"

#include <cmath>

namespace eyestream::io {

Chromaticities rec709_chromaticities() { return {0.640, 0.330, 0.300, 0.600, 0.150, 0.060, 0.3127, 0.3290}; }

Chromaticities bt2020_chromaticities() { return {0.708, 0.292, 0.170, 0.797, 0.131, 0.046, 0.3127, 0.3290}; }

namespace {

cv::Vec3d xyz_of(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

// RGB -> XYZ with Y(white) = 1 (SMPTE RP 177 construction).
cv::Matx33d rgb_to_xyz(const Chromaticities& c) {
  cv::Vec3d r = xyz_of(c.rx, c.ry), g = xyz_of(c.gx, c.gy), b = xyz_of(c.bx, c.by);
  cv::Matx33d p(r[0], g[0], b[0], r[1], g[1], b[1], r[2], g[2], b[2]);
  cv::Vec3d s = p.inv() * xyz_of(c.wx, c.wy);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p(i, j) *= s[j];
  return p;
}

// Bradford chromatic adaptation from white `src` to white `dst` (XYZ).
cv::Matx33d bradford(const cv::Vec3d& src, const cv::Vec3d& dst) {
  const cv::Matx33d bfd(0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296);
  cv::Vec3d s = bfd * src, d = bfd * dst;
  cv::Matx33d scale = cv::Matx33d::diag(cv::Vec3d(d[0] / s[0], d[1] / s[1], d[2] / s[2]));
  return bfd.inv() * scale * bfd;
}

}  // namespace

bool valid_chromaticities(const Chromaticities& c) {
  const double v[8] = {c.rx, c.ry, c.gx, c.gy, c.bx, c.by, c.wx, c.wy};
  for (double x : v)
    if (!std::isfinite(x)) return false;
  if (!(c.ry > 0 && c.gy > 0 && c.by > 0 && c.wy > 0)) return false;
  // The primaries span a triangle of non-zero area.
  const double area = (c.gx - c.rx) * (c.by - c.ry) - (c.bx - c.rx) * (c.gy - c.ry);
  return std::abs(area) > 1e-6;
}

cv::Matx33d to_rec709_matrix(const Chromaticities& from) {
  Chromaticities to = rec709_chromaticities();
  cv::Matx33d adapt = bradford(xyz_of(from.wx, from.wy), xyz_of(to.wx, to.wy));
  return rgb_to_xyz(to).inv() * adapt * rgb_to_xyz(from);
}

bool is_identity(const cv::Matx33d& m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::abs(m(i, j) - (i == j ? 1.0 : 0.0)) > 1e-6) return false;
  return true;
}

void apply_matrix(cv::Mat& rgb, const cv::Matx33d& m) {
  CV_Assert(rgb.type() == CV_32FC3);
  cv::transform(rgb, rgb, cv::Matx33f(m));
}

}  // namespace eyestream::io
