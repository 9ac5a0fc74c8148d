#include "glare/uniform_field.hpp"

#include <algorithm>

namespace eyestream::glare {

bool is_uniform_field(const cv::Mat& rgb, double surround, double tolerance) {
  CV_Assert(rgb.type() == CV_32FC3);
  // One sweep that stops at the first pixel proving the field is not
  // uniform (most frames: within the first rows).
  const double spread = 1.0 + tolerance;
  double lo[3], hi[3];
  for (int c = 0; c < 3; ++c) lo[c] = hi[c] = rgb.rows > 0 && rgb.cols > 0 ? rgb.at<cv::Vec3f>(0, 0)[c] : 0.0;
  for (int y = 0; y < rgb.rows; ++y) {
    const cv::Vec3f* p = rgb.ptr<cv::Vec3f>(y);
    for (int x = 0; x < rgb.cols; ++x)
      for (int c = 0; c < 3; ++c) {
        const double v = p[x][c];
        if (!(v >= 0.0)) return false;  // negative or NaN
        lo[c] = std::min(lo[c], v);
        hi[c] = std::max(hi[c], v);
        if (hi[c] > spread * lo[c]) return false;
      }
  }
  // The surround is grey: every channel must match it too, or a coloured
  // field would take the surround's colour at its edges.
  for (int c = 0; c < 3; ++c)
    if (surround < lo[c] / spread || surround > hi[c] * spread) return false;
  return true;
}

}  // namespace eyestream::glare
