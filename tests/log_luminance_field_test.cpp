#include "retina/log_luminance_field.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/test_support.hpp"

namespace eyestream::retina {
namespace {

TEST(LogLuminanceField, UniformFrameGivesItsLogLuminanceInside) {
  const LogLuminanceField field(test::constant_frame(40, 30, {100, 100, 100}), 1e-6);
  EXPECT_NEAR(field.patch_mean(20, 15, 5, -6), 2.0, 1e-9);
  EXPECT_NEAR(field.patch_mean(20.3, 14.6, 4.7, -6), 2.0, 1e-9);
}

TEST(LogLuminanceField, OutsideTheFrameCountsAsSurround) {
  const LogLuminanceField field(test::constant_frame(40, 30, {100, 100, 100}), 1e-6);
  // Centred on the left edge: half the patch sees the surround (log 0).
  EXPECT_NEAR(field.patch_mean(0, 15, 5, 0.0), 1.0, 1e-9);
  // Far outside: all surround.
  EXPECT_NEAR(field.patch_mean(-100, -100, 5, -1.0), -1.0, 1e-9);
}

TEST(LogLuminanceField, PatchAveragesLogsNotLuminances) {
  cv::Mat frame = test::constant_frame(2, 2, {1, 1, 1});
  frame.col(1).setTo(cv::Scalar(10000, 10000, 10000));
  const LogLuminanceField field(frame, 1e-6);
  EXPECT_NEAR(field.patch_mean(1, 1, 1.0, 0), 2.0, 1e-6);  // mean of log 0 and log 4
}

TEST(LogLuminanceField, BlackAndNonFinitePixelsCountAsTheFloor) {
  cv::Mat frame = test::constant_frame(2, 2, {0, 0, 0});
  frame.at<cv::Vec3f>(0, 1) = cv::Vec3f(INFINITY, 0, 0);
  frame.at<cv::Vec3f>(1, 1) = cv::Vec3f(NAN, 1, 1);
  const LogLuminanceField field(frame, 1e-4);
  EXPECT_NEAR(field.patch_mean(1, 1, 1.0, 0), -4.0, 1e-6);
}

}  // namespace
}  // namespace eyestream::retina
