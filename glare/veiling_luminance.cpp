#include "glare/veiling_luminance.hpp"

#include <cmath>

namespace eyestream::glare {

double veiling_luminance_between(const cv::Mat& luminance, const ComponentKernels& k, const PsfWeights& w, double x,
                                 double y, double exclusion_px) {
  CV_Assert(luminance.type() == CV_32F);
  const cv::Point c = k.centre();
  const cv::Mat* components[6] = {&k.core, &k.inner, &k.outer, &k.halo[0], &k.halo[1], &k.halo[2]};
  const double weights[6] = {w.core, w.inner, w.outer, 0.2126 * w.halo, 0.7152 * w.halo, 0.0722 * w.halo};
  // The four pixel centres around (x, y) and their bilinear weights; one
  // sweep over the sources for all four.
  const double u = x - 0.5, v = y - 0.5;
  const int px = int(std::floor(u)), py = int(std::floor(v));
  const double fu = u - px, fv = v - py;
  const double corner[4] = {(1 - fu) * (1 - fv), fu * (1 - fv), (1 - fu) * fv, fu * fv};
  double veil[4] = {0, 0, 0, 0};
  for (int r = 0; r < luminance.rows; ++r) {
    const float* l = luminance.ptr<float>(r);
    for (int q = 0; q < luminance.cols; ++q) {
      if (!(l[q] > 0.0f)) continue;
      for (int i = 0; i < 4; ++i) {
        const int ax = px + (i & 1), ay = py + (i >> 1);
        if (std::hypot(q - ax, r - ay) <= exclusion_px) continue;
        const int kx = c.x + ax - q, ky = c.y + ay - r;
        if (kx < 0 || ky < 0 || kx >= k.core.cols || ky >= k.core.rows) continue;
        double kernel = 0.0;
        for (int j = 0; j < 6; ++j) kernel += weights[j] * components[j]->at<double>(ky, kx);
        veil[i] += double(l[q]) * kernel;
      }
    }
  }
  return corner[0] * veil[0] + corner[1] * veil[1] + corner[2] * veil[2] + corner[3] * veil[3];
}

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
