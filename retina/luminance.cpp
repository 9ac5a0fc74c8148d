#include "retina/luminance.hpp"

#include <cmath>

namespace eyestream::retina {

cv::Mat floored_luminance(const cv::Mat& rgb, double floor_cd_m2) {
  CV_Assert(rgb.type() == CV_32FC3);
  cv::Mat l(rgb.size(), CV_32F);
  const float floor = float(floor_cd_m2);
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const cv::Vec3f* in = rgb.ptr<cv::Vec3f>(y);
      float* out = l.ptr<float>(y);
      for (int x = 0; x < rgb.cols; ++x) {
        const float v = photopic_luminance(in[x]);
        out[x] = (v > floor && std::isfinite(v)) ? v : floor;
      }
    }
  });
  return l;
}

}  // namespace eyestream::retina
