// glare/linear_taps.hpp against OpenCV's own linear resizing (the mapping
// it claims to reproduce): a random image enlarged by taps equals
// cv::resize(INTER_LINEAR) to float rounding, at an exact 2x and at odd
// sizes whose ratio is not 2 (a halved frame of odd size brought back).
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "glare/linear_taps.hpp"

namespace eyestream::glare {
namespace {

cv::Mat by_taps(const cv::Mat& small, cv::Size size) {
  const std::vector<LinearTap> cols = linear_taps(0, size.width, double(small.cols) / size.width, small.cols);
  const std::vector<LinearTap> rows = linear_taps(0, size.height, double(small.rows) / size.height, small.rows);
  cv::Mat out(size, CV_32F);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      const LinearTap& ty = rows[size_t(y)];
      const LinearTap& tx = cols[size_t(x)];
      const auto at = [&](int r, int c) { return small.at<float>(r, c); };
      const float top = at(ty.a, tx.a) * (1.0f - tx.wb) + at(ty.a, tx.b) * tx.wb;
      const float bottom = at(ty.b, tx.a) * (1.0f - tx.wb) + at(ty.b, tx.b) * tx.wb;
      out.at<float>(y, x) = top * (1.0f - ty.wb) + bottom * ty.wb;
    }
  return out;
}

TEST(LinearTaps, EnlargeAsOpenCvsLinearResize) {
  for (const auto& [small, large] : {std::pair{cv::Size(480, 270), cv::Size(960, 540)},
                                     std::pair{cv::Size(81, 46), cv::Size(161, 91)},
                                     std::pair{cv::Size(100, 40), cv::Size(333, 97)}}) {
    cv::Mat in(small, CV_32F);
    cv::randu(in, 0.0, 1.0);
    cv::Mat expected;
    cv::resize(in, expected, large, 0, 0, cv::INTER_LINEAR);
    EXPECT_LT(cv::norm(by_taps(in, large), expected, cv::NORM_INF), 1e-5) << small << " to " << large;  // (OpenCV weighs in float)
  }
}

}  // namespace
}  // namespace eyestream::glare
