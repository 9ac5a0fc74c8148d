#include "io/nonfinite_pixels.hpp"

#include "retina/bit_masks.hpp"
#include "retina/vector_clones.hpp"

namespace eyestream::io {

EYESTREAM_VECTOR_CLONES
int nonfinite_in_row(const float* p, int pixels) {
  int n = 0;
  for (int x = 0; x < pixels; ++x)
    n += int(!(retina::finite_bits(p[3 * x]) & retina::finite_bits(p[3 * x + 1]) & retina::finite_bits(p[3 * x + 2])));
  return n;
}

std::int64_t nonfinite_pixels(const cv::Mat& rgb) {
  CV_Assert(rgb.type() == CV_32FC3);
  std::int64_t n = 0;
  for (int y = 0; y < rgb.rows; ++y) n += nonfinite_in_row(rgb.ptr<float>(y), rgb.cols);
  return n;
}

}  // namespace eyestream::io
