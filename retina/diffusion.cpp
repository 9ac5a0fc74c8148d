#include "retina/diffusion.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace eyestream::retina {

void diffuse(cv::Mat& m, double variance) {
  if (!(variance > 0.0)) return;
  // Beyond the grid's own size a blur is as good as uniform: capped there,
  // so even an absurd time step stays a finite kernel.
  variance = std::min(variance, double(m.rows) * m.rows + double(m.cols) * m.cols);
  if (variance > 4.0) {
    const double sigma = std::sqrt(variance);
    cv::GaussianBlur(m, m, cv::Size(0, 0), sigma, sigma, cv::BORDER_REPLICATE);
    return;
  }
  const int passes = int(std::ceil(variance / 0.5));
  const double v = variance / passes;
  const cv::Mat k = (cv::Mat_<double>(3, 1) << v / 2, 1.0 - v, v / 2);
  for (int i = 0; i < passes; ++i) cv::sepFilter2D(m, m, -1, k, k, cv::Point(-1, -1), 0.0, cv::BORDER_REPLICATE);
}

}  // namespace eyestream::retina
