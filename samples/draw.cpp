#include "samples/draw.hpp"

#include <algorithm>
#include <cmath>

namespace eyestream::samples {

namespace {

void deposit(cv::Mat& frame, double x, double y, const cv::Vec3f& energy) {
  const double fx = x - 0.5, fy = y - 0.5;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const float ax = float(fx - x0), ay = float(fy - y0);
  const float w[4] = {(1 - ax) * (1 - ay), ax * (1 - ay), (1 - ax) * ay, ax * ay};
  const int xs[4] = {x0, x0 + 1, x0, x0 + 1}, ys[4] = {y0, y0, y0 + 1, y0 + 1};
  for (int k = 0; k < 4; ++k)
    if (xs[k] >= 0 && ys[k] >= 0 && xs[k] < frame.cols && ys[k] < frame.rows)
      frame.at<cv::Vec3f>(ys[k], xs[k]) += energy * w[k];
}

}  // namespace

void add_disc(cv::Mat& frame, double x, double y, double r, const cv::Vec3f& rgb) {
  if (r < 1.0) {
    deposit(frame, x, y, rgb * float(M_PI * r * r));
    return;
  }
  const int n = 8;
  const int x0 = std::max(0, int(std::floor(x - r))), x1 = std::min(frame.cols - 1, int(std::ceil(x + r)));
  const int y0 = std::max(0, int(std::floor(y - r))), y1 = std::min(frame.rows - 1, int(std::ceil(y + r)));
  for (int py = y0; py <= y1; ++py)
    for (int px = x0; px <= x1; ++px) {
      int hits = 0;
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx) {
          const double dx = px + (sx + 0.5) / n - x, dy = py + (sy + 0.5) / n - y;
          hits += dx * dx + dy * dy <= r * r;
        }
      if (hits) frame.at<cv::Vec3f>(py, px) += rgb * (float(hits) / float(n * n));
    }
}

cv::Vec3f with_luminance(const cv::Vec3f& tint, float luminance) {
  const float y = 0.2126f * tint[0] + 0.7152f * tint[1] + 0.0722f * tint[2];
  return tint * (luminance / y);
}

cv::Mat paint_rect(cv::Mat& frame, double x0, double y0, double x1, double y1, const cv::Vec3f& rgb) {
  cv::Mat mask = cv::Mat::zeros(frame.size(), CV_8U);
  const int u0 = std::max(0, int(std::floor(x0))), u1 = std::min(frame.cols, int(std::ceil(x1)));
  const int v0 = std::max(0, int(std::floor(y0))), v1 = std::min(frame.rows, int(std::ceil(y1)));
  for (int v = v0; v < v1; ++v) {
    const double cy = std::min<double>(v + 1, y1) - std::max<double>(v, y0);
    for (int u = u0; u < u1; ++u) {
      const double cover = cy * (std::min<double>(u + 1, x1) - std::max<double>(u, x0));
      if (cover <= 0) continue;
      cv::Vec3f& p = frame.at<cv::Vec3f>(v, u);
      p = p * float(1.0 - cover) + rgb * float(cover);
      if (cover >= 0.5) mask.at<unsigned char>(v, u) = 255;
    }
  }
  return mask;
}

}  // namespace eyestream::samples
