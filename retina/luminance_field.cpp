#include "retina/luminance_field.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "retina/log_sum.hpp"
#include "retina/luminance.hpp"
#include "retina/vector_clones.hpp"

namespace eyestream::retina {

namespace {

// sum_x a[x] w[x] over [x0, x1) in double (w = 1 when null), in eight
// partial sums added in a fixed order, so the loop runs as vectors
// (vector_clones.hpp) and gives the same value on any machine.
EYESTREAM_VECTOR_CLONES
double row_sum(const float* a, const float* w, int x0, int x1) {
  constexpr int kLanes = 8;
  double lanes[kLanes] = {};
  int x = x0;
  if (w) {
    for (; x + kLanes <= x1; x += kLanes)
      for (int k = 0; k < kLanes; ++k) lanes[k] += double(a[x + k]) * double(w[x + k]);
    for (int k = 0; x < x1; ++x, ++k) lanes[k] += double(a[x]) * double(w[x]);
  } else {
    for (; x + kLanes <= x1; x += kLanes)
      for (int k = 0; k < kLanes; ++k) lanes[k] += double(a[x + k]);
    for (int k = 0; x < x1; ++x, ++k) lanes[k] += double(a[x]);
  }
  double s = 0.0;
  for (double lane : lanes) s += lane;
  return s;
}

// Sum over rows [y0, y1) of sum_x l(y, x) w(y, x) for x in [x0, x1) (w = 1
// when empty), each row in double, rows added in order: the same value
// whatever the thread count.
double region_sum(const cv::Mat& l, const cv::Mat& w, int x0, int x1, int y0, int y1) {
  std::vector<double> rows(size_t(std::max(0, y1 - y0)), 0.0);
  const auto sum_rows = [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y)
      rows[size_t(y - y0)] = row_sum(l.ptr<float>(y), w.empty() ? nullptr : w.ptr<float>(y), x0, x1);
  };
  if (double(x1 - x0) * double(y1 - y0) > 1e5)
    cv::parallel_for_(cv::Range(y0, y1), sum_rows);
  else
    sum_rows(cv::Range(y0, y1));
  double total = 0.0;
  for (double s : rows) total += s;
  return total;
}

}  // namespace

LuminanceField::LuminanceField(const cv::Mat& rgb, double floor_cd_m2, const cv::Mat& weights)
    : luminance_(floored_luminance(rgb, floor_cd_m2)), weights_(weights) {
  CV_Assert(weights.empty() || (weights.type() == CV_32F && weights.size() == luminance_.size()));
}

double LuminanceField::frame_mean() const {
  if (mean_ >= 0.0) return mean_;
  const int cols = luminance_.cols, rows = luminance_.rows;
  if (weights_.empty())
    mean_ = region_sum(luminance_, cv::Mat(), 0, cols, 0, rows) / (double(cols) * double(rows));
  else
    mean_ = region_sum(luminance_, weights_, 0, cols, 0, rows) / region_sum(weights_, cv::Mat(), 0, cols, 0, rows);
  return mean_;
}

double sum_of_weights(const cv::Mat& weights) {
  return weights.empty() ? 0.0 : region_sum(weights, cv::Mat(), 0, weights.cols, 0, weights.rows);
}

SceneMeans scene_means(const cv::Mat& rgb, double floor_cd_m2, const cv::Mat& weights, double weight_total,
                       double band_px, const std::function<void(int)>& also_per_row) {
  CV_Assert(rgb.type() == CV_32FC3 && (weights.empty() || (weights.type() == CV_32F && weights.size() == rgb.size())));
  CV_Assert(floor_cd_m2 > 0.0);
  // Each row's floored luminance made once and read by both sums while in
  // cache; the rows' sums added in order: the same whatever the thread
  // count. The mean as the field's constructor and frame_mean() make it.
  const bool with_edge = band_px > 0.0;
  const int cols = rgb.cols, rows = rgb.rows;
  const int b = with_edge ? std::max(1, int(std::lround(band_px))) : 0;
  const bool all = 2 * b >= cols || 2 * b >= rows;
  std::vector<double> sums(size_t(rows), 0.0), logs(size_t(rows), 0.0);
  const float floor = float(floor_cd_m2);
  cv::parallel_for_(cv::Range(0, rows), [&](const cv::Range& r) {
    std::vector<float> l(static_cast<size_t>(cols));
    for (int y = r.start; y < r.end; ++y) {
      floored_luminance_row(rgb.ptr<float>(y), floor, l.data(), cols);
      if (also_per_row) also_per_row(y);
      sums[size_t(y)] = row_sum(l.data(), weights.empty() ? nullptr : weights.ptr<float>(y), 0, cols);
      if (!with_edge) continue;
      logs[size_t(y)] = (all || y < b || y >= rows - b) ? log2_sum(l.data(), cols)
                                                        : log2_sum(l.data(), b) + log2_sum(l.data() + cols - b, b);
    }
  });
  SceneMeans means;
  double total = 0.0, log_total = 0.0;
  for (double s : sums) total += s;
  for (double s : logs) log_total += s;
  means.mean = weights.empty() ? total / (double(cols) * double(rows)) : total / weight_total;
  if (with_edge) {
    const double band_pixels =
        all ? double(cols) * double(rows) : 2.0 * double(b) * double(cols) + 2.0 * double(b) * double(rows - 2 * b);
    means.edge = std::exp2(log_total / band_pixels);
  }
  return means;
}

double edge_log_mean(const cv::Mat& rgb, double band_px, double floor_cd_m2) {
  return scene_means(rgb, floor_cd_m2, cv::Mat(), 0.0, std::max(band_px, 0.5)).edge;
}

double LuminanceField::patch_log_mean(double x, double y, double half_x, double half_y, double surround_cd_m2) const {
  const int cols = luminance_.cols, rows = luminance_.rows;
  half_x = std::max(half_x, 0.5);
  half_y = std::max(half_y, 0.5);
  // The patch in whole pixels (at least one), then its part inside the frame.
  const long px0 = std::lround(x - half_x), py0 = std::lround(y - half_y);
  const long px1 = std::max(std::lround(x + half_x), px0 + 1), py1 = std::max(std::lround(y + half_y), py0 + 1);
  const int x0 = int(std::clamp<long>(px0, 0, cols)), x1 = int(std::clamp<long>(px1, 0, cols));
  const int y0 = int(std::clamp<long>(py0, 0, rows)), y1 = int(std::clamp<long>(py1, 0, rows));
  const double total = double(px1 - px0) * double(py1 - py0);
  const double inside = double(x1 - x0) * double(y1 - y0);
  double sum;
  if (inside <= kDirectSumPixels) {
    sum = region_sum(luminance_, cv::Mat(), x0, x1, y0, y1);
  } else {
    if (integral_.empty()) cv::integral(luminance_, integral_, CV_64F);
    sum = integral_.at<double>(y1, x1) - integral_.at<double>(y0, x1) - integral_.at<double>(y1, x0) +
          integral_.at<double>(y0, x0);
  }
  return std::log10((sum + (total - inside) * surround_cd_m2) / total);
}

}  // namespace eyestream::retina
