#include "glare/veiling_luminance.hpp"

#include <cmath>

namespace eyestream::glare {

double veiling_luminance(const cv::Mat& luminance, const ComponentKernels& k, const PsfWeights& w, double x, double y,
                         double exclusion_px) {
  CV_Assert(luminance.type() == CV_32F);
  const cv::Point c = k.centre();
  // The halo's luminance kernel: its R, G and B kernels by the Rec.709
  // luminance weights, as the picture's luminance combines them.
  const cv::Mat* components[6] = {&k.core, &k.inner, &k.outer, &k.halo[0], &k.halo[1], &k.halo[2]};
  const double weights[6] = {w.core, w.inner, w.outer, 0.2126 * w.halo, 0.7152 * w.halo, 0.0722 * w.halo};
  // The point's pixel: kernel offset (point - p) in whole pixels.
  const int px = int(std::floor(x)), py = int(std::floor(y));
  double veil = 0.0;
  for (int r = 0; r < luminance.rows; ++r) {
    const float* l = luminance.ptr<float>(r);
    for (int q = 0; q < luminance.cols; ++q) {
      if (!(l[q] > 0.0f) || std::hypot(q + 0.5 - x, r + 0.5 - y) <= exclusion_px) continue;
      const int kx = c.x + px - q, ky = c.y + py - r;
      if (kx < 0 || ky < 0 || kx >= k.core.cols || ky >= k.core.rows) continue;
      double kernel = 0.0;
      for (int i = 0; i < 6; ++i) kernel += weights[i] * components[i]->at<double>(ky, kx);
      veil += double(l[q]) * kernel;
    }
  }
  return veil;
}

double threshold_increment(double veil, double adaptation) { return 65.0 * veil / std::pow(adaptation, 0.8); }

bool threshold_increment_valid(double adaptation) { return adaptation >= 0.05 && adaptation <= 5.0; }

}  // namespace eyestream::glare
