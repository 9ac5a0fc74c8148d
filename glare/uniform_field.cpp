#include "glare/uniform_field.hpp"

namespace eyestream::glare {

bool is_uniform_field(const cv::Mat& rgb, double surround, double tolerance) {
  CV_Assert(rgb.type() == CV_32FC3);
  cv::Mat channels[3];
  cv::split(rgb, channels);
  double lo[3], hi[3];
  for (int c = 0; c < 3; ++c) {
    cv::minMaxLoc(channels[c], &lo[c], &hi[c]);
    if (!(lo[c] >= 0.0) || hi[c] > (1.0 + tolerance) * lo[c]) return false;
  }
  const double l_lo = 0.2126 * lo[0] + 0.7152 * lo[1] + 0.0722 * lo[2];
  const double l_hi = 0.2126 * hi[0] + 0.7152 * hi[1] + 0.0722 * hi[2];
  return surround >= l_lo / (1.0 + tolerance) && surround <= l_hi * (1.0 + tolerance);
}

}  // namespace eyestream::glare
