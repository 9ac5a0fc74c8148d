#include "retina/afterimage_composite.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "retina/bilinear_axis.hpp"
#include "retina/bit_masks.hpp"
#include "retina/enlarged_rows.hpp"
#include "retina/cone_space.hpp"
#include "retina/bilinear_rows.hpp"
#include "retina/vector_clones.hpp"

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

namespace {

// A 3x3 matrix times (x0, x1, x2), each row summed from 0 in order, as
// cv::Matx does (so a sum of zeros is +0, bit for bit).
struct Rows3 {
  float m[9];
  float row(int i, float x0, float x1, float x2) const {
    return ((0.0f + m[3 * i] * x0) + m[3 * i + 1] * x1) + m[3 * i + 2] * x2;
  }
};

Rows3 rows3(const cv::Matx33f& a) {
  Rows3 r;
  for (int i = 0; i < 9; ++i) r.m[i] = a.val[i];
  return r;
}

// One row of n pixels (interleaved RGB; the maps' LMS beside them), in a
// loop compiled for AVX-512 and AVX2 beside the baseline (vector_clones.hpp).
EYESTREAM_VECTOR_CLONES
void composite_row(const float* j, const float* g, const float* b, Rows3 to_lms, Rows3 to_rgb, Rows3 h, float* o,
                   int n) {
  for (int x = 0; x < n; ++x) {
    const float j0 = j[3 * x], j1 = j[3 * x + 1], j2 = j[3 * x + 2];
    const float g0 = g[3 * x], g1 = g[3 * x + 1], g2 = g[3 * x + 2];
    const float b0 = b[3 * x], b1 = b[3 * x + 1], b2 = b[3 * x + 2];
    const float l0 = to_lms.row(0, j0, j1, j2), l1 = to_lms.row(1, j0, j1, j2), l2 = to_lms.row(2, j0, j1, j2);
    const float e0 = l0 + l0 * g0, e1 = l1 + l1 * g1, e2 = l2 + l2 * g2;
    // At rest: every map value +0 or -0 (no bit but the sign set).
    const std::uint32_t any = (bits_of(g0) | bits_of(g1) | bits_of(g2) | bits_of(b0) | bits_of(b1) | bits_of(b2)) << 1;
    const std::uint32_t rest = mask_if(any == 0u);
    const float v0 = to_rgb.row(0, e0, e1, e2) + h.row(0, b0, b1, b2);
    const float v1 = to_rgb.row(1, e0, e1, e2) + h.row(1, b0, b1, b2);
    const float v2 = to_rgb.row(2, e0, e1, e2) + h.row(2, b0, b1, b2);
    o[3 * x] = pick(rest, j0, v0);
    o[3 * x + 1] = pick(rest, j1, v1);
    o[3 * x + 2] = pick(rest, j2, v2);
  }
}

}  // namespace

void composite_afterimages(const cv::Mat& tone_mapped, const cv::Mat& gain, const cv::Mat& bleach, cv::Mat& out) {
  // `gain` holds alpha^j2 - 1.
  CV_Assert(tone_mapped.type() == CV_32FC3 && gain.type() == CV_32FC3 && gain.size() == bleach.size() &&
            bleach.type() == CV_32FC3 && gain.cols <= tone_mapped.cols && gain.rows <= tone_mapped.rows);
  const Rows3 to_lms = rows3(rgb_to_lms_f()), to_rgb = rows3(lms_to_rgb_f()), h = rows3(afterimage_matrix_f());
  const bool full = gain.size() == tone_mapped.size();
  const int w = tone_mapped.cols;
  const BilinearAxis across(full ? 0 : w, gain.cols, float(gain.cols) / float(w));
  const BilinearAxis down(full ? 0 : tone_mapped.rows, gain.rows, float(gain.rows) / float(tone_mapped.rows));
  out.create(tone_mapped.size(), CV_32FC3);
  cv::parallel_for_(cv::Range(0, tone_mapped.rows), [&](const cv::Range& rows) {
    std::vector<float> g_row(full ? 0 : size_t(w) * 3), b_row(full ? 0 : size_t(w) * 3);
    std::optional<EnlargedRows> g_rows, b_rows;
    if (!full) g_rows.emplace(gain, across, w), b_rows.emplace(bleach, across, w);
    for (int y = rows.start; y < rows.end; ++y) {
      const float* g = gain.ptr<float>(full ? y : 0);
      const float* b = bleach.ptr<float>(full ? y : 0);
      if (!full) {  // the maps' row, enlarged: across, then the blend of two rows down
        const size_t iy = size_t(y);
        blend_rows(g_rows->row(down.lo[iy]), g_rows->row(down.hi[iy]), down.w[iy], g_row.data(), 3 * w);
        blend_rows(b_rows->row(down.lo[iy]), b_rows->row(down.hi[iy]), down.w[iy], b_row.data(), 3 * w);
        g = g_row.data();
        b = b_row.data();
      }
      composite_row(tone_mapped.ptr<float>(y), g, b, to_lms, to_rgb, h, out.ptr<float>(y), w);
    }
  }, double(std::max(1, cv::getNumThreads()) * 4));  // stripes of rows, each enlarging a map row once
}

}  // namespace eyestream::retina
