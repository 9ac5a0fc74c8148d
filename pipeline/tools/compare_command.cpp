#include "pipeline/tools/compare_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "io/display_sequence.hpp"
#include "io/error.hpp"
#include "io/frame_sequence.hpp"
#include "io/png_file.hpp"
#include "io/staged_file.hpp"
#include "retina/colour_difference.hpp"

namespace eyestream::pipeline {

namespace {

constexpr double kDisplayGamma = 2.2;  // decodes display code values (eyestream encodes with 1/2.2)

struct FrameMetrics {
  double max_abs = 0, mean_abs = 0, psnr = 0, de_p99 = 0, de_max = 0, frac_over = 0, frac_warn = 0;
  cv::Point worst;  // where de_max is
};

// Per-pixel CIEDE2000 (CV_32F) and the frame's metrics; rows in parallel,
// each pixel written once, so the result does not depend on threads.
FrameMetrics measure(const cv::Mat& a, const cv::Mat& b, bool linear, double de_threshold, double de_warn,
                     cv::Mat& de) {
  de = retina::ciede2000_map(a, b, linear ? 1.0 : kDisplayGamma);
  FrameMetrics m;
  const cv::Mat diff = cv::abs(a - b);
  cv::minMaxLoc(diff.reshape(1), nullptr, &m.max_abs);
  const cv::Scalar mean = cv::mean(diff);
  m.mean_abs = (mean[0] + mean[1] + mean[2]) / 3;
  const double mse = cv::mean(diff.mul(diff)).dot(cv::Scalar(1, 1, 1, 0)) / 3;
  m.psnr = mse > 0 ? 10 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
  std::vector<float> values(de.begin<float>(), de.end<float>());
  if (values.empty()) return m;  // an empty frame: nothing differs
  const size_t k = std::min(values.size() - 1, size_t(std::ceil(0.99 * values.size())) - 1);
  std::nth_element(values.begin(), values.begin() + k, values.end());
  m.de_p99 = values[k];
  cv::minMaxLoc(de, nullptr, &m.de_max, nullptr, &m.worst);
  m.frac_over = double(cv::countNonZero(de > de_threshold)) / double(de.total());
  m.frac_warn = double(cv::countNonZero(de > de_warn)) / double(de.total());
  return m;
}

// The judged value; for `visible`, `warning` picks the share beyond de_warn.
double judged(const FrameMetrics& m, const std::string& metric, bool warning = false) {
  if (metric == "visible") return warning ? m.frac_warn : m.frac_over;
  if (metric == "de99") return m.de_p99;
  if (metric == "demax") return m.de_max;
  if (metric == "max") return m.max_abs;
  if (metric == "mean") return m.mean_abs;
  return m.psnr;
}

// True when `value` is beyond `limit` for this metric (PSNR: below it).
bool beyond(double value, double limit, const std::string& metric) {
  return metric == "psnr" ? value < limit : value > limit;
}

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json to_json(const FrameMetrics& m) {
  return {{"max_abs", m.max_abs}, {"mean_abs", m.mean_abs}, {"psnr_db", number_or_null(m.psnr)},
          {"de2000_p99", m.de_p99}, {"de2000_max", m.de_max}, {"fraction_over_threshold", m.frac_over},
          {"fraction_over_warn", m.frac_warn}};
}

std::string format_metrics(const FrameMetrics& m) {
  char buf[256];
  std::snprintf(buf, sizeof(buf), "max abs %.6g, mean abs %.3g, PSNR %.2f dB, p99 dE00 %.3f, max dE00 %.3f, %.4g%% over",
                m.max_abs, m.mean_abs, m.psnr, m.de_p99, m.de_max, 100 * m.frac_over);
  return buf;
}

// A CIEDE2000 heat map: black at 0, full scale at `scale`.
cv::Mat heat_map(const cv::Mat& de, double scale) {
  cv::Mat grey, colour;
  de.convertTo(grey, CV_8U, 255.0 / scale);
  cv::applyColorMap(grey, colour, cv::COLORMAP_INFERNO);
  return colour;
}

}  // namespace

CompareResult compare(const CompareOptions& o) {
  io::DisplaySequence a(o.a, o.layer), b(o.b, o.layer);
  CompareResult result;
  std::vector<io::StagedFile> diffs;
  nlohmann::json frames = nlohmann::json::array();
  FrameMetrics overall;
  overall.psnr = std::numeric_limits<double>::infinity();
  retina::DeltaEHistogram histogram;
  std::uint64_t pixels = 0, over = 0;
  double worst = o.metric == "psnr" ? std::numeric_limits<double>::infinity() : 0.0, worst_warn = 0.0;
  std::int64_t worst_frame = 0, count = 0;
  std::string worst_pixel;  // where the largest CIEDE2000 is, and the two values
  const double warn = o.warn.value_or(o.metric == "visible" ? 0.0 : 0.5);
  const double fail = o.fail.value_or(o.metric == "visible" ? 0.0 : 1.0);
  std::string mismatch;
  if (a.kind() != b.kind())
    mismatch = "A holds " + std::string(a.kind_name()) + " frames and B " + b.kind_name() + " ones";
  if (mismatch.empty() && a.frame_count() >= 0 && b.frame_count() >= 0 && a.frame_count() != b.frame_count())
    mismatch = "A has " + std::to_string(a.frame_count()) + " frames, B " + std::to_string(b.frame_count());
  while (mismatch.empty()) {
    std::optional<io::DisplayImage> fa = a.next(), fb = b.next();
    if (!fa && !fb) break;
    if (!fa || !fb) {
      mismatch = std::string(fa ? "B" : "A") + " ends after " + std::to_string(count) + " frames, the other goes on";
      break;
    }
    if (fa->rgb.size() != fb->rgb.size()) {
      mismatch = fa->name + " is " + std::to_string(fa->rgb.cols) + "x" + std::to_string(fa->rgb.rows) + " but " +
                 fb->name + " is " + std::to_string(fb->rgb.cols) + "x" + std::to_string(fb->rgb.rows);
      break;
    }
    cv::Mat de;
    const FrameMetrics m = measure(fa->rgb, fb->rgb, a.linear(), o.de_threshold, o.de_warn, de);
    if (count == 0 || m.de_max > overall.de_max) {
      const cv::Vec3f va = fa->rgb.at<cv::Vec3f>(m.worst), vb = fb->rgb.at<cv::Vec3f>(m.worst);
      char at[256];
      std::snprintf(at, sizeof(at), "largest CIEDE2000 %.3g at %s, x %d, y %d: A (%.4g, %.4g, %.4g), B (%.4g, %.4g, %.4g)",
                    m.de_max, fb->name.c_str(), m.worst.x, m.worst.y, va[0], va[1], va[2], vb[0], vb[1], vb[2]);
      worst_pixel = at;
    }
    worst_warn = std::max(worst_warn, m.frac_warn);
    histogram.add(de);
    pixels += de.total();
    over += std::uint64_t(std::llround(m.frac_over * double(de.total())));
    overall.max_abs = std::max(overall.max_abs, m.max_abs);
    overall.mean_abs += m.mean_abs;
    overall.psnr = std::min(overall.psnr, m.psnr);
    overall.de_max = std::max(overall.de_max, m.de_max);
    const double v = judged(m, o.metric);
    if (count == 0 || beyond(v, worst, o.metric)) worst = v, worst_frame = fa->number;
    frames.push_back(to_json(m));
    frames.back()["frame"] = fa->number;
    if (o.verbose) result.text += "frame " + std::to_string(fa->number) + ": " + format_metrics(m) + "\n";
    if (!o.diff_out.empty()) {
      // Named by the first input's frame number, so a map sits beside its frame.
      diffs.emplace_back(io::format_pattern(o.diff_out, fa->number));
      io::write_all(diffs.back(), io::encode_png(heat_map(de, o.diff_scale)));
    }
    ++count;
  }
  if (count > 0) {
    overall.mean_abs /= double(count);
    overall.de_p99 = histogram.quantile(0.99);  // rounded down to the bin
    overall.frac_over = double(over) / double(pixels);
  }
  const bool visible = o.metric == "visible";
  const double warn_value = visible ? worst_warn : worst;
  std::string verdict = "pass";
  if (!mismatch.empty()) verdict = "fail";
  else if (count > 0 && beyond(worst, fail, o.metric)) verdict = "fail";
  else if (count > 0 && beyond(warn_value, warn, o.metric)) verdict = "warn";
  result.exit_code = verdict == "pass" ? 0 : verdict == "warn" ? 1 : 2;
  char line[320];
  if (visible)
    std::snprintf(line, sizeof(line),
                  "; the worst frame has %.4g%% of its pixels beyond CIEDE2000 %.3g (fail above %.4g%%) and %.4g%% "
                  "beyond %.3g (warn above %.4g%%): %s",
                  100 * worst, o.de_threshold, 100 * fail, 100 * worst_warn, o.de_warn, 100 * warn, verdict.c_str());
  else
    std::snprintf(line, sizeof(line), "; %s of the worst frame (%lld) %.6g against warn %.6g, fail %.6g: %s",
                  o.metric.c_str(), (long long)worst_frame, worst, warn, fail, verdict.c_str());
  if (!mismatch.empty())  // the metrics of a partial comparison would mislead
    result.text += "compare: fail: " + mismatch + "\n";
  else
    result.text += "compare: " + std::to_string(count) + " frames; " + format_metrics(overall) +
                   " (overall p99 rounded down to 0.01)" + (count > 0 ? std::string(line) : "; " + verdict) + "\n" +
                   (count > 0 ? "compare: " + worst_pixel + "\n" : "");
  if (!o.json.empty()) {
    nlohmann::json report = {{"a", o.a},          {"b", o.b},         {"metric", o.metric}, {"warn", warn},
                              {"fail", fail},      {"frames", frames}, {"overall", to_json(overall)},
                              {"result", verdict}, {"worst_frame", worst_frame}, {"worst_pixel", worst_pixel}};
    if (!mismatch.empty()) report["mismatch"] = mismatch;
    const std::string text = report.dump(2) + "\n";
    io::StagedFile file(o.json);
    io::write_all(file, std::vector<unsigned char>(text.begin(), text.end()));
    file.commit();
  }
  for (io::StagedFile& f : diffs) f.commit();
  return result;
}

}  // namespace eyestream::pipeline
