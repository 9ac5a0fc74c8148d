#include "retina/cone_space.hpp"

#include <Eigen/LU>

namespace eyestream::retina {

namespace {

Eigen::Matrix3d make_rgb_to_lms() {
  Eigen::Matrix3d rgb_to_xyz;  // IEC 61966-2-1 (sRGB / Rec.709 primaries, D65)
  rgb_to_xyz << 0.4124564, 0.3575761, 0.1804375, 0.2126729, 0.7151522, 0.0721750, 0.0193339, 0.1191920, 0.9503041;
  Eigen::Matrix3d hpe;  // Hunt-Pointer-Estevez, normalised to D65
  hpe << 0.4002, 0.7076, -0.0808, -0.2263, 1.1653, 0.0457, 0.0, 0.0, 0.9182;
  Eigen::Matrix3d m = hpe * rgb_to_xyz;
  // Exact normalisation: each row scaled so RGB (1,1,1) gives 1.
  const Eigen::Vector3d white = m * Eigen::Vector3d::Ones();
  for (int r = 0; r < 3; ++r) m.row(r) /= white(r);
  return m;
}

cv::Matx33f to_cv(const Eigen::Matrix3d& m) {
  cv::Matx33f out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out(r, c) = float(m(r, c));
  return out;
}

}  // namespace

const Eigen::Matrix3d& rgb_to_lms() {
  static const Eigen::Matrix3d m = make_rgb_to_lms();
  return m;
}

const Eigen::Matrix3d& lms_to_rgb() {
  static const Eigen::Matrix3d m = rgb_to_lms().inverse();
  return m;
}

const Eigen::Matrix3d& afterimage_matrix() {
  static const Eigen::Matrix3d h = [] {
    Eigen::Matrix3d m;  // Jacobs et al. 2015 App. A, H
    m << 1.14, -1.18, 0.36, -0.08, 1.02, 0.18, 0.30, -0.11, 1.25;
    return m;
  }();
  return h;
}

cv::Matx33f rgb_to_lms_f() { return to_cv(rgb_to_lms()); }
cv::Matx33f lms_to_rgb_f() { return to_cv(lms_to_rgb()); }
cv::Matx33f afterimage_matrix_f() { return to_cv(afterimage_matrix()); }

}  // namespace eyestream::retina
