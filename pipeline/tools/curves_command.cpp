#include "pipeline/tools/curves_command.hpp"

#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "io/png_file.hpp"

namespace eyestream::pipeline {

void write_tone_curves(const retina::ToneCurveParams& tone, const std::string& path) {
  const int w = 800, h = 480, left = 70, right = 20, top = 30, bottom = 60;
  cv::Mat img(h, w, CV_8UC3, cv::Scalar(255, 255, 255));
  const double lo = -6, hi = 8;
  auto px = [&](double log_l) { return int(left + (log_l - lo) / (hi - lo) * (w - left - right)); };
  auto py = [&](double r) { return int(h - bottom - r * (h - top - bottom)); };
  const cv::Scalar axis(60, 60, 60), grid(225, 225, 225);
  for (int l = int(lo); l <= int(hi); ++l) {
    cv::line(img, {px(l), py(0)}, {px(l), py(1)}, grid);
    cv::putText(img, std::to_string(l), {px(l) - 8, h - bottom + 20}, cv::FONT_HERSHEY_SIMPLEX, 0.45, axis);
  }
  for (int k = 0; k <= 4; ++k) {
    const double r = k / 4.0;
    cv::line(img, {px(lo), py(r)}, {px(hi), py(r)}, grid);
    char label[8];
    std::snprintf(label, sizeof(label), "%.2f", r);
    cv::putText(img, label, {left - 45, py(r) + 4}, cv::FONT_HERSHEY_SIMPLEX, 0.45, axis);
  }
  cv::putText(img, "log10 luminance (cd/m^2)", {w / 2 - 100, h - 15}, cv::FONT_HERSHEY_SIMPLEX, 0.5, axis);
  cv::putText(img, "R", {15, py(0.5)}, cv::FONT_HERSHEY_SIMPLEX, 0.6, axis);
  const cv::Scalar colours[6] = {{180, 60, 40}, {200, 120, 0}, {60, 160, 60},
                                 {0, 140, 220}, {30, 60, 200}, {120, 40, 160}};
  int i = 0;
  for (double a : {-4.0, -2.0, 0.0, 2.0, 4.0, 6.0}) {
    const retina::ToneCurve curve(a, tone);
    std::vector<cv::Point> points;
    for (double l = lo; l <= hi; l += 0.02) points.push_back({px(l), py(curve.response(float(std::pow(10.0, l))))});
    cv::polylines(img, points, false, colours[i], 2, cv::LINE_AA);
    cv::circle(img, {px(a), py(retina::plateau(a, tone))}, 5, colours[i], cv::FILLED, cv::LINE_AA);
    cv::putText(img, "A=" + std::to_string(int(a)), {px(a) - 16, py(retina::plateau(a, tone)) - 10},
                cv::FONT_HERSHEY_SIMPLEX, 0.45, colours[i]);
    ++i;
  }
  for (double l = lo; l < hi; l += 0.2)
    cv::line(img, {px(l), py(retina::plateau(l, tone))}, {px(l + 0.1), py(retina::plateau(l + 0.1, tone))}, axis, 1,
             cv::LINE_AA);
  cv::putText(img, "Naka-Rushton R(I) per adaptation level A; dots and dashes: the plateau M(A)", {left, 20},
              cv::FONT_HERSHEY_SIMPLEX, 0.5, axis);
  io::write_png(path, img);
}

}  // namespace eyestream::pipeline
