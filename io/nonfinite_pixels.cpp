#include "io/nonfinite_pixels.hpp"

#include <cstdint>
#include <cstring>

namespace eyestream::io {

namespace {

// All ones in the exponent: NaN or infinite. Tested by bits so the row loop
// has no branch and vectorises (io stands alone: retina/bit_masks.hpp has
// the same test for the eye's loops).
inline std::uint32_t exponent_all_ones(float v) {
  std::uint32_t b;
  std::memcpy(&b, &v, sizeof b);
  return std::uint32_t((b & 0x7f800000u) == 0x7f800000u);
}

}  // namespace

// Compiled for AVX2 beside the baseline, chosen at start (GCC only).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
int nonfinite_in_row(const float* p, int pixels) {
  int n = 0;
  for (int x = 0; x < pixels; ++x)
    n += int(exponent_all_ones(p[3 * x]) | exponent_all_ones(p[3 * x + 1]) | exponent_all_ones(p[3 * x + 2]));
  return n;
}

std::int64_t nonfinite_pixels(const cv::Mat& rgb) {
  CV_Assert(rgb.type() == CV_32FC3);
  std::int64_t n = 0;
  for (int y = 0; y < rgb.rows; ++y) n += nonfinite_in_row(rgb.ptr<float>(y), rgb.cols);
  return n;
}

}  // namespace eyestream::io
