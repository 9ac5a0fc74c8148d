// remap_maps (pipeline/geometry/remap_maps.hpp) against OpenCV's own
// cv::convertMaps of the shifted positions, bit for bit: positions over a
// plane and beyond its edges (negative ones, whose whole part floors),
// exact ties of the fixed-point rounding (even and odd, either sign),
// positions whose shift by 0.5 itself rounds (small ones, either sign),
// whole parts past a short's range (saturated, either sign), and a
// frame-sized case; and through cv::remap, the samples the maps give.
#include "pipeline/geometry/remap_maps.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <opencv2/imgproc.hpp>

namespace eyestream::pipeline {
namespace {

void expect_as_convert_maps(const cv::Mat& positions) {
  cv::Mat want1, want2, got1, got2;
  const cv::Mat shifted = positions - cv::Scalar(0.5, 0.5);
  cv::convertMaps(shifted, cv::Mat(), want1, want2, CV_16SC2);
  remap_maps(positions, got1, got2);
  ASSERT_EQ(got1.type(), CV_16SC2);
  ASSERT_EQ(got2.type(), CV_16UC1);
  ASSERT_EQ(got1.size(), positions.size());
  for (int y = 0; y < positions.rows; ++y) {
    ASSERT_EQ(std::memcmp(got1.ptr(y), want1.ptr(y), size_t(positions.cols) * 4), 0) << "row " << y;
    ASSERT_EQ(std::memcmp(got2.ptr(y), want2.ptr(y), size_t(positions.cols) * 2), 0) << "row " << y;
  }
}

TEST(RemapMaps, AreConvertMapsOfTheShiftedPositionsBitForBit) {
  cv::RNG random(17);
  cv::Mat spread(61, 97, CV_32FC2);
  random.fill(spread, cv::RNG::UNIFORM, -3.0, 120.0);
  expect_as_convert_maps(spread);
  // Row 0: ties, (p - 0.5) x 32 = k + 0.5 for k even and odd, either
  // sign; rows 1 and 3: more ties at other scales; row 2: p - 0.5 rounded
  // (p small, either sign) and whole parts beyond a short's range.
  cv::Mat ties(4, 64, CV_32FC2);
  for (int x = 0; x < 64; ++x) {
    const float k = float(x - 32) + 0.5f;
    ties.at<cv::Vec2f>(0, x) = cv::Vec2f(0.5f + k / 32.0f, 0.5f - k / 32.0f);
    ties.at<cv::Vec2f>(1, x) = cv::Vec2f(0.5f + float(x) / 64.0f, 0.5f + float(x) / 32.0f);
    ties.at<cv::Vec2f>(2, x) = x < 60 ? cv::Vec2f(-0.49f + float(x) * 0.0071f, 1e-3f * float(x) + 1e-5f)
                                      : cv::Vec2f(x % 2 ? -2e6f : 2e6f, x % 2 ? 1048576.3f : -1048576.3f);
    ties.at<cv::Vec2f>(3, x) = cv::Vec2f(-0.5f + float(x) / 1024.0f, 700.25f + float(x) / 128.0f);
  }
  expect_as_convert_maps(ties);
  cv::Mat frame(1080, 1920, CV_32FC2);
  random.fill(frame, cv::RNG::UNIFORM, -0.5, 1900.0);
  expect_as_convert_maps(frame);
}

TEST(RemapMaps, SampleAsTheFloatPositionsDo) {
  // cv::remap through these maps and through the shifted float positions
  // (which OpenCV converts the same way) give the same samples.
  cv::RNG random(18);
  cv::Mat image(40, 50, CV_32FC3), positions(30, 35, CV_32FC2);
  random.fill(image, cv::RNG::UNIFORM, 0.0, 1e4);
  random.fill(positions, cv::RNG::UNIFORM, -0.5, 50.0);
  cv::Mat m1, m2, got, want;
  remap_maps(positions, m1, m2);
  cv::remap(image, got, m1, m2, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  cv::remap(image, want, positions - cv::Scalar(0.5, 0.5), cv::Mat(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  EXPECT_EQ(cv::norm(got, want, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(got, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace eyestream::pipeline
