#include "pipeline/report/report_charts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "io/delimited_table.hpp"
#include "io/error.hpp"
#include "io/png_file.hpp"
#include "io/staged_file.hpp"

namespace eyestream::pipeline {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double cell(const io::DelimitedTable& t, size_t row, int col, const std::string& origin) {
  const std::string& f = t.rows[row].at(col);
  if (f.empty()) return kNaN;
  double v;
  if (!io::parse_number(f, v))
    throw InputError(origin + ":" + std::to_string(t.line_numbers[row]) + ": column " + t.header[col] +
                     ": not a number: '" + f + "'");
  return v;
}

// Drawing (BGR, 8-bit).
const cv::Scalar kInk(50, 50, 50), kGrid(228, 228, 228), kBlink(215, 215, 215), kGlare(0, 140, 255);
const cv::Scalar kLine[6] = {{180, 90, 30}, {40, 40, 200}, {60, 150, 60}, {160, 60, 160}, {0, 140, 220}, {90, 90, 90}};
constexpr int kWidth = 1000, kLeft = 80, kRight = 20, kPanelH = 150, kGap = 34, kTop = 44;

struct Line {
  const std::vector<double>* ys;
  size_t series;  // its viewer: colour and times
  bool dashed;
};

struct Chart {
  std::string title;
  bool log;
  std::vector<Line> lines;
};

void text(cv::Mat& img, const std::string& s, cv::Point at, double scale = 0.42, cv::Scalar c = kInk) {
  cv::putText(img, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, c, 1, cv::LINE_AA);
}

std::string tick_label(double v, bool log) {
  char buf[32];
  if (log) std::snprintf(buf, sizeof(buf), "1e%d", int(std::lround(v)));
  else std::snprintf(buf, sizeof(buf), "%.3g", v);
  return buf;
}

void draw_chart(cv::Mat& img, int top, const Chart& c, const std::vector<ReportSeries>& series, double t0, double t1) {
  const int x0 = kLeft, x1 = kWidth - kRight, y0 = top, y1 = top + kPanelH;
  auto px = [&](double t) { return x0 + (t - t0) / std::max(t1 - t0, 1e-9) * (x1 - x0); };
  auto value = [&](double v) { return c.log ? (v > 0 ? std::log10(v) : kNaN) : v; };
  double lo = 1e300, hi = -1e300;
  for (const Line& line : c.lines)
    for (double v : *line.ys)
      if (std::isfinite(value(v))) lo = std::min(lo, value(v)), hi = std::max(hi, value(v));
  if (lo > hi) lo = 0, hi = 1;
  if (c.log) lo = std::floor(lo), hi = std::max(std::ceil(hi), lo + 1);
  else lo = std::min(lo, 0.0), hi = hi > lo ? hi + 0.1 * (hi - lo) : lo + 1;
  auto py = [&](double v) { return y1 - (v - lo) / (hi - lo) * (y1 - y0); };
  // Blinks of the first series, shaded behind everything.
  const ReportSeries& first = series[0];
  for (size_t i = 0; i < first.time_s.size(); ++i)
    if (first.eye_closed[i]) {
      const double next = i + 1 < first.time_s.size() ? first.time_s[i + 1] : first.time_s[i];
      cv::rectangle(img, cv::Point(int(px(first.time_s[i])), y0), cv::Point(int(std::ceil(px(next))), y1), kBlink,
                    cv::FILLED);
    }
  const int ticks = c.log ? int(hi - lo) : 4;
  const int step = std::max(1, ticks / 5);
  for (int k = 0; k <= ticks; k += step) {
    const double v = lo + (hi - lo) * k / ticks;
    cv::line(img, {x0, int(py(v))}, {x1, int(py(v))}, kGrid);
    text(img, tick_label(v, c.log), {8, int(py(v)) + 4});
  }
  cv::rectangle(img, {x0, y0}, {x1, y1}, kInk);
  text(img, c.title, {x0, y0 - 8}, 0.5);
  for (const Line& line : c.lines) {
    const ReportSeries& s = series[line.series];
    const std::vector<double>& ys = *line.ys;
    const cv::Scalar colour = kLine[line.series % 6];
    for (size_t i = 1; i < ys.size(); ++i) {
      const double a = value(ys[i - 1]), b = value(ys[i]);
      if (!std::isfinite(a) || !std::isfinite(b)) continue;
      const cv::Point2d p0(px(s.time_s[i - 1]), py(a)), p1(px(s.time_s[i]), py(b));
      if (!line.dashed) {
        cv::line(img, p0, p1, colour, 2, cv::LINE_AA);
        continue;
      }
      for (double x = std::floor(p0.x / 8) * 8; x < p1.x; x += 8) {  // 8 px dashes on even multiples
        if (int(x / 8) % 2) continue;
        const double xa = std::max(x, p0.x), xb = std::min(x + 8, p1.x);
        if (xb <= xa) continue;
        auto at = [&](double xx) { return cv::Point2d(xx, p0.y + (p1.y - p0.y) * (xx - p0.x) / (p1.x - p0.x)); };
        cv::line(img, at(xa), at(xb), colour, 2, cv::LINE_AA);
      }
    }
  }
}

bool any_finite(const std::vector<double>& v) {
  return std::any_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

}  // namespace

std::vector<ReportSeries> parse_report(const std::string& csv_text, const std::string& origin) {
  const io::DelimitedTable t = io::parse_delimited(csv_text, ',');
  const char* names[] = {"time_s",     "viewer",     "eye",      "adaptation_cd_m2", "pupil_mm",
                         "veil_cd_m2", "ti_percent", "contrast", "contrast_veiled",  "glare"};
  int col[10];
  for (int k = 0; k < 10; ++k)
    if ((col[k] = t.column(names[k])) < 0)
      throw InputError(origin + ": not an eyestream report (no column '" + names[k] + "')");
  std::vector<ReportSeries> out;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    if (t.rows[r].size() != t.header.size())
      throw InputError(origin + ":" + std::to_string(t.line_numbers[r]) + ": expected " +
                       std::to_string(t.header.size()) + " fields");
    const std::string& label = t.rows[r][col[1]];
    auto it = std::find_if(out.begin(), out.end(), [&](const ReportSeries& s) { return s.label == label; });
    if (it == out.end()) {
      out.emplace_back();
      out.back().label = label;
      it = out.end() - 1;
    }
    it->time_s.push_back(cell(t, r, col[0], origin));
    it->eye_closed.push_back(t.rows[r][col[2]] == "closed");
    it->adaptation_cd_m2.push_back(cell(t, r, col[3], origin));
    it->pupil_mm.push_back(cell(t, r, col[4], origin));
    it->veil_cd_m2.push_back(cell(t, r, col[5], origin));
    it->ti_percent.push_back(cell(t, r, col[6], origin));
    it->contrast.push_back(std::abs(cell(t, r, col[7], origin)));
    it->contrast_veiled.push_back(std::abs(cell(t, r, col[8], origin)));
    it->glare_ran.push_back(t.rows[r][col[9]] == "1");
    if (!std::isfinite(it->time_s.back()))
      throw InputError(origin + ":" + std::to_string(t.line_numbers[r]) + ": empty time_s");
  }
  if (out.empty()) throw InputError(origin + ": the report has no rows");
  return out;
}

void write_report_charts(const std::vector<ReportSeries>& series, const std::string& png_path) {
  stage_report_charts(series, png_path).commit();
}

io::StagedFile stage_report_charts(const std::vector<ReportSeries>& series, const std::string& png_path) {
  std::vector<Chart> charts = {{"adaptation luminance (cd/m^2)", true, {}},
                               {"pupil diameter (mm)", false, {}},
                               {"veiling luminance at the gaze (cd/m^2)", true, {}},
                               {"threshold increment TI (%)", false, {}}};
  for (size_t i = 0; i < series.size(); ++i) {
    charts[0].lines.push_back({&series[i].adaptation_cd_m2, i, false});
    charts[1].lines.push_back({&series[i].pupil_mm, i, false});
    charts[2].lines.push_back({&series[i].veil_cd_m2, i, false});
    charts[3].lines.push_back({&series[i].ti_percent, i, false});
  }
  if (any_finite(series[0].contrast)) {
    Chart contrast{"target |contrast|: solid without the veil, dashed with it", true, {}};
    for (size_t i = 0; i < series.size(); ++i) {
      contrast.lines.push_back({&series[i].contrast, i, false});
      contrast.lines.push_back({&series[i].contrast_veiled, i, true});
    }
    charts.push_back(contrast);
  }
  const int strip = 24;
  const int height = kTop + int(charts.size()) * (kPanelH + kGap) + strip + 40;
  cv::Mat img(height, kWidth, CV_8UC3, cv::Scalar(255, 255, 255));
  double t0 = 1e300, t1 = -1e300;
  for (const ReportSeries& s : series)
    for (double t : s.time_s) t0 = std::min(t0, t), t1 = std::max(t1, t);
  // Legend: one colour per viewer; blinks; glare activity.
  int x = kLeft;
  for (size_t i = 0; i < series.size(); ++i) {
    cv::line(img, {x, 18}, {x + 24, 18}, kLine[i % 6], 3);
    text(img, series[i].label, {x + 30, 23}, 0.5);
    x += 50 + 11 * int(series[i].label.size());
  }
  cv::rectangle(img, {x, 10}, {x + 24, 26}, kBlink, cv::FILLED);
  text(img, "eyes closed", {x + 30, 23}, 0.5);
  int top = kTop + 16;
  for (const Chart& c : charts) {
    draw_chart(img, top, c, series, t0, t1);
    top += kPanelH + kGap;
  }
  // Stage activity: where the glare stage ran (first viewer).
  const ReportSeries& s = series[0];
  auto px = [&](double t) { return kLeft + (t - t0) / std::max(t1 - t0, 1e-9) * (kWidth - kRight - kLeft); };
  for (size_t i = 0; i < s.time_s.size(); ++i)
    if (s.glare_ran[i]) {
      const double next = i + 1 < s.time_s.size() ? s.time_s[i + 1] : s.time_s[i];
      cv::rectangle(img, cv::Point(int(px(s.time_s[i])), top - 16), cv::Point(int(std::ceil(px(next))), top - 16 + strip),
                    kGlare, cv::FILLED);
    }
  cv::rectangle(img, {kLeft, top - 16}, {kWidth - kRight, top - 16 + strip}, kInk);
  text(img, "glare ran", {8, top}, 0.42);
  char axis[64];
  std::snprintf(axis, sizeof(axis), "time (s), %.2f to %.2f", t0, t1);
  text(img, axis, {kWidth / 2 - 80, top + strip + 14}, 0.5);
  return io::stage_png(png_path, img);
}

void draw_report_file(const std::string& csv_path, const std::string& png_path) {
  io::protect_input(csv_path);
  std::ifstream in(csv_path, std::ios::binary);
  if (!in) throw InputError(csv_path + ": cannot open the report");
  std::ostringstream text;
  text << in.rdbuf();
  write_report_charts(parse_report(text.str(), csv_path), png_path);
}

}  // namespace eyestream::pipeline
