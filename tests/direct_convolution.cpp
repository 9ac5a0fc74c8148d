#include "direct_convolution.hpp"

#include <algorithm>
#include <cmath>

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

glare::ComponentKernels falloff_kernels(int r) {
  glare::ComponentKernels k;
  k.core = cv::Mat::zeros(2 * r + 1, 2 * r + 1, CV_64F);
  for (int y = -r; y <= r; ++y)
    for (int x = -r; x <= r; ++x) k.core.at<double>(y + r, x + r) = 1.0 / std::pow(1.0 + std::hypot(x, y), 3);
  k.core /= cv::sum(k.core)[0];
  k.inner = k.outer = k.halo[0] = k.halo[1] = k.halo[2] = cv::Mat::zeros(k.core.size(), CV_64F);
  return k;
}

glare::PsfWeights core_only() {
  glare::PsfWeights w;
  w.core = 1.0, w.inner = w.outer = w.halo = 0.0;
  return w;
}

cv::Mat road_with_headlight(int width, int height) {
  cv::Mat in(height, width, CV_32FC3, cv::Scalar::all(0.01));
  in.at<cv::Vec3f>(90, 160) = cv::Vec3f::all(1e5f);
  return in;
}

double worst_road_error(const cv::Mat& out, int r) {
  const cv::Mat want =
      direct_convolution(cv::Mat(out.size(), CV_32FC3, cv::Scalar::all(0.01)), falloff_kernels(r), core_only());
  double worst = 0;
  for (int y = 0; y < out.rows; y += 7)
    for (int x = 0; x < out.cols; x += 7)
      if (std::max(std::abs(x - 160), std::abs(y - 90)) > r)
        worst = std::max(worst, std::abs(double(out.at<cv::Vec3f>(y, x)[1]) - want.at<cv::Vec3d>(y, x)[1]));
  return worst;
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
