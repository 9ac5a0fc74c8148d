#include "retina/tone_map.hpp"

#include <cmath>

#include "retina/luminance.hpp"

namespace eyestream::retina {

void tone_map(const cv::Mat& rgb, const ToneCurve& curve, cv::Mat& out) {
  CV_Assert(rgb.type() == CV_32FC3);
  out.create(rgb.size(), CV_32FC3);
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const cv::Vec3f* in = rgb.ptr<cv::Vec3f>(y);
      cv::Vec3f* o = out.ptr<cv::Vec3f>(y);
      for (int x = 0; x < rgb.cols; ++x) {
        const cv::Vec3f p = in[x];
        const float l = photopic_luminance(p);
        if (!(l > 0.0f) || !std::isfinite(l)) {
          o[x] = cv::Vec3f(0, 0, 0);
          continue;
        }
        o[x] = p * (curve.response(l) / l);
      }
    }
  });
}

}  // namespace eyestream::retina
