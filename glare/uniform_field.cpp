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
  // The surround is grey: every channel must match it too, or a coloured
  // field would take the surround's colour at its edges.
  for (int c = 0; c < 3; ++c)
    if (surround < lo[c] / (1.0 + tolerance) || surround > hi[c] * (1.0 + tolerance)) return false;
  return true;
}

}  // namespace eyestream::glare
