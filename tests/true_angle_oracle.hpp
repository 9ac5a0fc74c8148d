// The oracle of the true-angle tests: a rectilinear frame's pixels as rays
// from a pinhole, written out from the camera model alone (no eyestream
// geometry), and the veil they cast by direct summation over pixels.
#pragma once

#include <cmath>
#include <functional>
#include <opencv2/core.hpp>

namespace eyestream::test {

struct PinholeFrame {
  int width, height;
  double fov_deg;  // horizontal
  double focal_px() const { return 0.5 * width / std::tan(0.5 * fov_deg * M_PI / 180.0); }
  // The unit ray through frame point (x, y), origin at the top-left corner.
  cv::Vec3d ray(double x, double y) const {
    const cv::Vec3d d(x - 0.5 * width, y - 0.5 * height, focal_px());
    return d / cv::norm(d);
  }
  double angle_deg(cv::Point2d a, cv::Point2d b) const {
    const cv::Vec3d p = ray(a.x, a.y), q = ray(b.x, b.y);
    return std::atan2(cv::norm(p.cross(q)), p.dot(q)) * 180.0 / M_PI;
  }
  // Solid angle (sr) of pixel (x, y): its area over the squared distance,
  // foreshortened by the ray's cosine to the axis.
  double pixel_sr(int x, int y) const {
    const double f = focal_px(), dx = x + 0.5 - 0.5 * width, dy = y + 0.5 - 0.5 * height;
    return f / std::pow(dx * dx + dy * dy + f * f, 1.5);
  }
  // The frame point t deg from the centre along the horizontal.
  double x_at_deg(double t) const { return 0.5 * width + focal_px() * std::tan(t * M_PI / 180.0); }
};

// The luminance scattered onto frame point p from every pixel of
// `luminance` (CV_32F) more than exclusion_deg away: sum of L dOmega P(t),
// P the PSF per steradian at the true angle t.
inline double direct_veil(const PinholeFrame& frame, const cv::Mat& luminance, cv::Point2d p,
                          const std::function<double(double)>& psf, double exclusion_deg) {
  double veil = 0.0;
  for (int y = 0; y < luminance.rows; ++y)
    for (int x = 0; x < luminance.cols; ++x) {
      const float l = luminance.at<float>(y, x);
      if (!(l > 0.0f)) continue;
      const double t = frame.angle_deg(p, {x + 0.5, y + 0.5});
      if (t > exclusion_deg) veil += l * frame.pixel_sr(x, y) * psf(t);
    }
  return veil;
}

}  // namespace eyestream::test
