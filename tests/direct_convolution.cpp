#include "direct_convolution.hpp"

namespace eyestream::test {

glare::ComponentKernels random_kernels(int r, unsigned seed, bool symmetric) {
  cv::RNG rng(seed);
  glare::ComponentKernels k;
  cv::Mat* parts[6] = {&k.core, &k.inner, &k.outer, &k.halo[0], &k.halo[1], &k.halo[2]};
  for (cv::Mat* m : parts) {
    m->create(2 * r + 1, 2 * r + 1, CV_64F);
    rng.fill(*m, cv::RNG::UNIFORM, 0.0, 1.0);
    cv::Mat turned;
    cv::flip(*m, turned, -1);
    if (symmetric) *m += turned;
    *m /= cv::sum(*m)[0];
  }
  return k;
}

cv::Mat direct_convolution(const cv::Mat& in, const glare::ComponentKernels& k, const glare::PsfWeights& w) {
  const int r = k.core.cols / 2;
  cv::Mat out = cv::Mat::zeros(in.size(), CV_64FC3);
  for (int c = 0; c < 3; ++c) {
    const cv::Mat kc = w.core * k.core + w.inner * k.inner + w.outer * k.outer + w.halo * k.halo[c];
    for (int y = 0; y < in.rows; ++y)
      for (int x = 0; x < in.cols; ++x) {
        double sum = 0;
        for (int dy = -r; dy <= r; ++dy) {
          const int sy = y - dy;
          if (sy < 0 || sy >= in.rows) continue;
          const cv::Vec3f* row = in.ptr<cv::Vec3f>(sy);
          const double* kr = kc.ptr<double>(dy + r);
          for (int dx = -r; dx <= r; ++dx) {
            const int sx = x - dx;
            if (sx < 0 || sx >= in.cols) continue;
            sum += row[sx][c] * kr[dx + r];
          }
        }
        out.at<cv::Vec3d>(y, x)[c] = sum;
      }
  }
  return out;
}

}  // namespace eyestream::test
