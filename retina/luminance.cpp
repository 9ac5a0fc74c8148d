#include "retina/luminance.hpp"

#include <cmath>

#include "retina/bit_masks.hpp"
#include "retina/vector_clones.hpp"

namespace eyestream::retina {

// The test by bits and the choice by a mask, so the loop has no branch and
// is vectorised (vector_clones.hpp).
EYESTREAM_VECTOR_CLONES
void floored_luminance_row(const float* in, float floor, float* out, int n) {
  for (int x = 0; x < n; ++x) {
    const float v = kPhotopicR * in[3 * x] + kPhotopicG * in[3 * x + 1] + kPhotopicB * in[3 * x + 2];
    out[x] = pick(mask_if((v > floor) & finite_bits(v)), v, floor);
  }
}

cv::Mat floored_luminance(const cv::Mat& rgb, double floor_cd_m2) {
  CV_Assert(rgb.type() == CV_32FC3);
  cv::Mat l(rgb.size(), CV_32F);
  const float floor = float(floor_cd_m2);
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) floored_luminance_row(rgb.ptr<float>(y), floor, l.ptr<float>(y), rgb.cols);
  });
  return l;
}

}  // namespace eyestream::retina
