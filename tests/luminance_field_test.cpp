#include "retina/luminance_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "pipeline/eye/pixel_checks.hpp"
#include "retina/luminance.hpp"
#include "tests/test_support.hpp"

namespace eyestream::retina {
namespace {

TEST(LuminanceField, UniformFrameGivesItsLogLuminanceInside) {
  const LuminanceField field(test::constant_frame(40, 30, {100, 100, 100}), 1e-6);
  EXPECT_NEAR(field.patch_log_mean(20, 15, 5, 1e-6), 2.0, 1e-9);
  EXPECT_NEAR(field.patch_log_mean(20.3, 14.6, 4.7, 1e-6), 2.0, 1e-9);
  EXPECT_NEAR(field.frame_mean(), 100.0, 1e-9);
}

TEST(LuminanceField, OutsideTheFrameCountsAsSurround) {
  const LuminanceField field(test::constant_frame(40, 30, {100, 100, 100}), 1e-6);
  // Centred on the left edge: half the patch sees the surround (1 cd/m^2).
  EXPECT_NEAR(field.patch_log_mean(0, 15, 5, 1.0), std::log10(50.5), 1e-9);
  // Far outside: all surround.
  EXPECT_NEAR(field.patch_log_mean(-100, -100, 5, 0.1), -1.0, 1e-9);
}

// Jacobs et al. 2015, sec. 2.1: the target is the log of the average
// luminance, not the average of log luminance. A patch half 1000 and half
// 1 cd/m^2 adapts to 500.5 cd/m^2 (the log mean would give 31.6).
TEST(LuminanceField, PatchAveragesLuminancesNotLogs) {
  cv::Mat frame = test::constant_frame(2, 2, {1, 1, 1});
  frame.col(1).setTo(cv::Scalar(1000, 1000, 1000));
  const LuminanceField field(frame, 1e-6);
  EXPECT_NEAR(field.patch_log_mean(1, 1, 1.0, 1.0), std::log10(500.5), 1e-6);
}

TEST(EdgeLogMean, TheGeometricMeanOfTheOuterBandAndNothingInside) {
  cv::Mat frame = test::constant_frame(40, 30, {10, 10, 10});
  frame(cv::Rect(4, 4, 32, 22)).setTo(cv::Scalar::all(1e6));  // inside the 4 px band: ignored
  EXPECT_NEAR(edge_log_mean(frame, 4, 1e-6), 10.0, 1e-9);
  // Half the band at 1000, half at 10... by area: left and right columns.
  cv::Mat halves = test::constant_frame(40, 30, {10, 10, 10});
  halves.colRange(0, 20).setTo(cv::Scalar::all(1000));
  EXPECT_NEAR(edge_log_mean(halves, 4, 1e-6), 100.0, 1e-6) << "geometric: one bright side does not dominate";
  // A band as wide as the frame is the whole frame.
  EXPECT_NEAR(edge_log_mean(test::constant_frame(6, 6, {2, 2, 2}), 4, 1e-6), 2.0, 1e-9);
}

TEST(LuminanceField, BlackAndNonFinitePixelsCountAsTheFloor) {
  cv::Mat frame = test::constant_frame(2, 2, {0, 0, 0});
  frame.at<cv::Vec3f>(0, 1) = cv::Vec3f(INFINITY, 0, 0);
  frame.at<cv::Vec3f>(1, 1) = cv::Vec3f(NAN, 1, 1);
  const LuminanceField field(frame, 1e-4);
  EXPECT_NEAR(field.patch_log_mean(1, 1, 1.0, 1.0), -4.0, 1e-6);
}

TEST(FrameMeanLuminance, IsTheFieldsMeanBitForBitWithAndWithoutWeights) {
  // The pupil's field is taken in one pass when the field itself is not
  // read: it must be the same number, not a close one (outputs stay
  // byte-identical). The oracle for the value itself is the mean computed
  // here in long double, weighted by hand.
  cv::Mat rgb(37, 53, CV_32FC3), weights(37, 53, CV_32F);
  cv::RNG rng(7);
  rng.fill(rgb, cv::RNG::UNIFORM, cv::Scalar::all(-1.0), cv::Scalar::all(2e4));
  rng.fill(weights, cv::RNG::UNIFORM, 0.2, 1.0);
  rgb.at<cv::Vec3f>(3, 4)[1] = std::numeric_limits<float>::quiet_NaN();
  const double floor = 1e-3;
  long double sum = 0, weighted = 0, total_weight = 0;
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x) {
      const float l = photopic_luminance(rgb.at<cv::Vec3f>(y, x));
      const long double v = (std::isfinite(l) && l > float(floor)) ? l : float(floor);
      sum += v;
      weighted += v * weights.at<float>(y, x);
      total_weight += weights.at<float>(y, x);
    }
  const double plain = scene_means(rgb, floor, cv::Mat(), 0.0, 0.0).mean;
  const double with_weights = scene_means(rgb, floor, weights, sum_of_weights(weights), 0.0).mean;
  EXPECT_EQ(plain, LuminanceField(rgb, floor).frame_mean());
  EXPECT_EQ(with_weights, LuminanceField(rgb, floor, weights).frame_mean());
  EXPECT_NEAR(plain, double(sum / (37 * 53)), 1e-9 * plain);
  EXPECT_NEAR(with_weights, double(weighted / total_weight), 1e-9 * with_weights);
  EXPECT_NE(plain, with_weights);
  // The same with the edge's logs and a per-row callback in the pass, as
  // the eye runs it.
  EXPECT_EQ(scene_means(rgb, floor, weights, sum_of_weights(weights), 4.0, [](int) {}).mean, with_weights);
}

}  // namespace
}  // namespace eyestream::retina

// The floored luminance and the non-finite count, by their definitions
// written out here, over every kind of value, on a row whose width leaves
// the vector loops a tail.
TEST(PixelChecks, FlooredLuminanceAndNonFiniteCountByTheirDefinitions) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float values[] = {0.0f, -0.0f, -3.0f, 1e-9f, 1e-6f, 0.5f, 7.0f, 3e38f, inf, -inf, nan, 1e-42f};
  cv::Mat rgb(3, 37, CV_32FC3);
  cv::RNG rng(3);
  std::int64_t bad = 0;
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x) {
      cv::Vec3f& p = rgb.at<cv::Vec3f>(y, x);
      for (int c = 0; c < 3; ++c) p[c] = values[rng.uniform(0, 12)];
      bad += !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
    }
  EXPECT_EQ(eyestream::pipeline::count_nonfinite(rgb), bad);
  EXPECT_GT(bad, 0);
  const float floor = 1e-6f;
  const cv::Mat l = eyestream::retina::floored_luminance(rgb, floor);
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x) {
      const float v = eyestream::retina::photopic_luminance(rgb.at<cv::Vec3f>(y, x));
      const float want = (v > floor && std::isfinite(v)) ? v : floor;
      EXPECT_EQ(std::memcmp(&want, &l.at<float>(y, x), sizeof want), 0) << x << "," << y;
    }
}
