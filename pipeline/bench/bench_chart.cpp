#include "pipeline/bench/bench_chart.hpp"

#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>

#include "io/png_file.hpp"

namespace eyestream::pipeline {

namespace {

constexpr int kW = 900, kH = 560, kLeft = 80, kRight = 90, kTop = 50, kBottom = 60;

void label(cv::Mat& img, const std::string& s, cv::Point at, double scale = 0.45) {
  cv::putText(img, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(40, 40, 40), 1, cv::LINE_AA);
}

cv::Scalar size_colour(size_t i) {
  static const cv::Scalar colours[] = {{180, 100, 30}, {40, 120, 220}, {60, 160, 60}, {150, 60, 160}};
  return colours[i % 4];
}

}  // namespace

void draw_bench_chart(const std::vector<BenchRow>& rows, const std::string& path) {
  std::vector<const BenchRow*> points;
  for (const BenchRow& r : rows)
    if (r.skip && (r.preset == "reference" || r.against == "reference")) points.push_back(&r);
  double lo = 1e9, hi = 0, top = 1.0;
  for (const BenchRow* r : points) {
    lo = std::min(lo, r->figures.filter_ms);
    hi = std::max(hi, r->figures.filter_ms);
    top = std::max(top, r->error.de_p99 * 1.15);
  }
  const double x0 = std::floor(std::log10(std::max(lo, 0.1))), x1 = std::ceil(std::log10(std::max(hi, 1.0)) + 1e-9);
  auto px = [&](double ms) { return kLeft + int((std::log10(ms) - x0) / std::max(x1 - x0, 1.0) * (kW - kLeft - kRight)); };
  auto py = [&](double de) { return kH - kBottom - int(de / top * (kH - kTop - kBottom)); };

  cv::Mat img(kH, kW, CV_8UC3, cv::Scalar(255, 255, 255));
  cv::rectangle(img, {kLeft, kTop}, {kW - kRight, kH - kBottom}, cv::Scalar(120, 120, 120));
  for (double e = x0; e <= x1 + 1e-9; e += 1) {
    const int x = px(std::pow(10.0, e));
    cv::line(img, {x, kTop}, {x, kH - kBottom}, cv::Scalar(225, 225, 225));
    label(img, std::to_string(int(std::lround(std::pow(10.0, e)))), {x - 12, kH - kBottom + 18});
  }
  for (int k = 0; k <= 4; ++k) {
    const double de = top * k / 4;
    const int y = py(de);
    cv::line(img, {kLeft, y}, {kW - kRight, y}, cv::Scalar(225, 225, 225));
    char buf[16];
    std::snprintf(buf, sizeof(buf), "%.2f", de);
    label(img, buf, {kLeft - 50, y + 5});
  }
  label(img, "filter time per frame [ms], log scale", {kW / 2 - 140, kH - 18}, 0.5);
  label(img, "p99 CIEDE2000 against reference", {10, 30}, 0.5);
  if (!points.empty()) label(img, "scene: " + points.front()->scene, {kW - 260, 30}, 0.5);

  std::map<std::string, std::vector<const BenchRow*>> by_size;
  std::vector<std::string> order;
  for (const BenchRow* r : points) {
    if (!by_size.count(r->size)) order.push_back(r->size);
    by_size[r->size].push_back(r);
  }
  for (size_t i = 0; i < order.size(); ++i) {
    std::vector<const BenchRow*> line = by_size[order[i]];
    std::sort(line.begin(), line.end(),
              [](const BenchRow* a, const BenchRow* b) { return a->figures.filter_ms < b->figures.filter_ms; });
    const cv::Scalar colour = size_colour(i);
    for (size_t k = 0; k < line.size(); ++k) {
      const cv::Point p(px(line[k]->figures.filter_ms), py(line[k]->error.de_p99));
      if (k > 0)
        cv::line(img, {px(line[k - 1]->figures.filter_ms), py(line[k - 1]->error.de_p99)}, p, colour, 2, cv::LINE_AA);
      cv::circle(img, p, 6, colour, cv::FILLED, cv::LINE_AA);
      label(img, line[k]->preset, {p.x + 8, p.y - 8});
    }
    cv::circle(img, {kLeft + 20, kTop + 20 + 22 * int(i)}, 6, colour, cv::FILLED, cv::LINE_AA);
    label(img, order[i], {kLeft + 32, kTop + 25 + 22 * int(i)});
  }
  io::write_png(path, img);
}

}  // namespace eyestream::pipeline
