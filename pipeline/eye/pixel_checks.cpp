#include "pipeline/eye/pixel_checks.hpp"

#include <cmath>
#include <vector>

#include "io/nonfinite_pixels.hpp"

namespace eyestream::pipeline {

std::int64_t count_nonfinite(const cv::Mat& rgb) {
  CV_Assert(rgb.type() == CV_32FC3);
  std::vector<std::int64_t> per_row(size_t(rgb.rows), 0);
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) per_row[size_t(y)] = io::nonfinite_in_row(rgb.ptr<float>(y), rgb.cols);
  });
  std::int64_t total = 0;
  for (std::int64_t n : per_row) total += n;
  return total;
}

cv::Mat finite_copy(const cv::Mat& rgb) {
  cv::Mat out = rgb.clone();
  out.forEach<cv::Vec3f>([](cv::Vec3f& p, const int*) {
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) p = cv::Vec3f(0, 0, 0);
  });
  return out;
}

cv::Mat one_channel_if_grey(const cv::Mat& map) {
  CV_Assert(map.type() == CV_32FC3);
  for (int y = 0; y < map.rows; ++y) {
    const cv::Vec3f* p = map.ptr<cv::Vec3f>(y);
    for (int x = 0; x < map.cols; ++x)
      if (!(p[x][0] == p[x][1] && p[x][0] == p[x][2])) return map;
  }
  cv::Mat grey(map.size(), CV_32F);
  cv::extractChannel(map, grey, 0);
  return grey;
}

}  // namespace eyestream::pipeline
