#include "retina/afterimage_composite.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include "retina/bilinear_axis.hpp"

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
  CV_Assert(tone_mapped.type() == CV_32FC3 && gain.type() == CV_32FC3 && gain.size() == bleach.size() &&
            gain.cols <= tone_mapped.cols && gain.rows <= tone_mapped.rows);
  const cv::Matx33f to_lms = rgb_to_lms_f(), to_rgb = lms_to_rgb_f(), h = afterimage_matrix_f();
  const bool full = gain.size() == tone_mapped.size();
  const BilinearAxis across(full ? 0 : tone_mapped.cols, gain.cols, float(gain.cols) / float(tone_mapped.cols));
  const BilinearAxis down(full ? 0 : tone_mapped.rows, gain.rows, float(gain.rows) / float(tone_mapped.rows));
  out.create(tone_mapped.size(), CV_32FC3);
  cv::parallel_for_(cv::Range(0, tone_mapped.rows), [&](const cv::Range& rows) {
    std::vector<cv::Vec3f> g_row, b_row;
    for (int y = rows.start; y < rows.end; ++y) {
      const cv::Vec3f* j = tone_mapped.ptr<cv::Vec3f>(y);
      const cv::Vec3f* g = gain.ptr<cv::Vec3f>(full ? y : 0);
      const cv::Vec3f* b = bleach.ptr<cv::Vec3f>(full ? y : 0);
      if (!full) {  // the maps' row, enlarged
        g_row.resize(size_t(tone_mapped.cols));
        b_row.resize(size_t(tone_mapped.cols));
        const size_t iy = size_t(y);
        const float fy = down.w[iy];
        for (const auto& [map, row] : {std::pair{&gain, &g_row}, std::pair{&bleach, &b_row}}) {
          const cv::Vec3f* r0 = map->ptr<cv::Vec3f>(down.lo[iy]);
          const cv::Vec3f* r1 = map->ptr<cv::Vec3f>(down.hi[iy]);
          for (int x = 0; x < tone_mapped.cols; ++x) {
            const size_t ix = size_t(x);
            const float fx = across.w[ix];
            const int x0 = across.lo[ix], x1 = across.hi[ix];
            (*row)[ix] = (r0[x0] * (1.0f - fx) + r0[x1] * fx) * (1.0f - fy) + (r1[x0] * (1.0f - fx) + r1[x1] * fx) * fy;
          }
        }
        g = g_row.data();
        b = b_row.data();
      }
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
