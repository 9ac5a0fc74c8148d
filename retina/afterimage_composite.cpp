#include "retina/afterimage_composite.hpp"

#include <cmath>

#include "retina/cone_space.hpp"

namespace eyestream::retina {

cv::Mat to_cone_stimulus(const cv::Mat& rgb, int depth) {
  CV_Assert(rgb.type() == CV_32FC3);
  cv::Mat lms;
  cv::transform(rgb, lms, rgb_to_lms_f());
  lms.forEach<cv::Vec3f>([](cv::Vec3f& p, const int*) {
    for (int c = 0; c < 3; ++c)
      if (!(std::isfinite(p[c]) && p[c] > 0.0f)) p[c] = 0.0f;
  });
  if (depth == CV_64F) lms.convertTo(lms, CV_64FC3);
  return lms;
}

void composite_afterimages(const cv::Mat& tone_mapped, const cv::Mat& gain, const cv::Mat& bleach, cv::Mat& out) {
  // `gain` holds alpha^j2 - 1.
  CV_Assert(tone_mapped.type() == CV_32FC3 && gain.size() == tone_mapped.size() && bleach.size() == tone_mapped.size());
  const cv::Matx33f to_lms = rgb_to_lms_f(), to_rgb = lms_to_rgb_f(), h = afterimage_matrix_f();
  out.create(tone_mapped.size(), CV_32FC3);
  cv::parallel_for_(cv::Range(0, tone_mapped.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const cv::Vec3f* j = tone_mapped.ptr<cv::Vec3f>(y);
      const cv::Vec3f* g = gain.ptr<cv::Vec3f>(y);
      const cv::Vec3f* b = bleach.ptr<cv::Vec3f>(y);
      cv::Vec3f* o = out.ptr<cv::Vec3f>(y);
      for (int x = 0; x < tone_mapped.cols; ++x) {
        const bool at_rest = g[x] == cv::Vec3f(0, 0, 0) && b[x] == cv::Vec3f(0, 0, 0);
        if (at_rest) {
          o[x] = j[x];
          continue;
        }
        const cv::Vec3f lms = to_lms * j[x];
        o[x] = to_rgb * (lms + lms.mul(g[x])) + h * b[x];
      }
    }
  });
}

}  // namespace eyestream::retina
