#include "retina/halve_frame.hpp"

#include <opencv2/imgproc.hpp>

#include "retina/pixel_vector.hpp"

namespace eyestream::retina {

namespace {

// One output row of three-channel pixels from input rows a and b: each
// value (0 + (a[x] + a[x + 3] + b[x] + b[x + 3])) / 4, OpenCV's terms in
// OpenCV's order (its plain loop, whose sum starts at +0: a block of -0
// gives +0; its vector code, which one channel takes, adds in pairs and
// leaves a tail that depends on its width). A pixel's three values at
// once: the fourth lane reads the next input pixel's first value and
// writes the next output pixel's, which that pixel then writes; the last
// pixel, which has no next one, a value at a time.
void halve_row(const float* __restrict a, const float* __restrict b, float* __restrict out, int pixels) {
  const PixelVector zero = {0, 0, 0, 0}, quarter = {0.25f, 0.25f, 0.25f, 0.25f};
  int x = 0;
  for (; x + 1 < pixels; ++x) {
    const float* p = a + 6 * size_t(x);
    const float* q = b + 6 * size_t(x);
    const PixelVector v =
        (zero + (((four_floats(p) + four_floats(p + 3)) + four_floats(q)) + four_floats(q + 3))) * quarter;
    store_four(out + 3 * size_t(x), v);
  }
  for (; x < pixels; ++x)
    for (int c = 0; c < 3; ++c)
      out[3 * x + c] = (0.0f + (a[6 * x + c] + a[6 * x + 3 + c] + b[6 * x + c] + b[6 * x + 3 + c])) * 0.25f;
}

}  // namespace

void halve_frame(const cv::Mat& in, cv::Mat& out) {
  const cv::Size half((in.cols + 1) / 2, (in.rows + 1) / 2);
  const bool ours = in.type() == CV_32FC3 && in.cols % 2 == 0 && in.rows % 2 == 0;
  if (!ours) {
    cv::resize(in, out, half, 0, 0, cv::INTER_AREA);
    return;
  }
  CV_Assert(out.data != in.data || out.empty());
  out.create(half, in.type());
  cv::parallel_for_(cv::Range(0, half.height), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y)
      halve_row(in.ptr<float>(2 * y), in.ptr<float>(2 * y + 1), out.ptr<float>(y), half.width);
  });
}

}  // namespace eyestream::retina
