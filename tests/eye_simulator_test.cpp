#include "pipeline/eye/eye_simulator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/test_support.hpp"

namespace eyestream::pipeline {
namespace {

constexpr int kW = 48, kH = 27;
constexpr double kFps = 30.0;

// These tests are about adaptation and the tone curve: optics off, so a
// uniform field stays uniform (glare scatters some of it out of the frame).
Settings no_glare() {
  Settings s;
  s.glare = false;
  return s;
}

Plan test_plan() {
  io::SourceInfo info;
  info.width = kW;
  info.height = kH;
  info.frames_per_second = kFps;
  return compile_plan(no_glare(), info);
}

cv::Scalar mean_rgb(EyeSimulator& eye, float luminance, int index, bool closed = false) {
  io::SceneFrame frame{test::constant_frame(kW, kH, {luminance, luminance, luminance}), index / kFps, index, "test"};
  const std::vector<GazeSegment> gaze = {{index / kFps, (index + 1) / kFps, kW / 2.0, kH / 2.0, closed}};
  return cv::mean(eye.process(frame, gaze).linear);
}

double mean_output(EyeSimulator& eye, float luminance, int index, bool closed = false) {
  return mean_rgb(eye, luminance, index, closed)[1];
}

// Jacobs et al. 2015 sec. 2.1 and fig. 2: stepping from a dark to a bright scene, the
// output starts bright and darkens over the following second as the viewer
// adapts at a1 = 0.75 log units/s.
TEST(EyeSimulator, StepFromDarkToBrightDarkensOverTheFollowingSecond) {
  EyeSimulator eye(test_plan());
  for (int i = 0; i < 30; ++i) mean_output(eye, 0.1f, i);
  EXPECT_NEAR(eye.adaptation_log(), -1.0, 1e-7);  // 0.1f is 0.1 to 1.5e-8
  std::vector<double> after;
  for (int i = 30; i < 60; ++i) after.push_back(mean_output(eye, 100.0f, i));
  for (size_t k = 1; k < after.size(); ++k) EXPECT_LT(after[k], after[k - 1]) << k;
  // The model's size of the effect: J falls from 0.889 to 0.797 (display
  // codes 242 to 230 after gamma 0.455) as A rises from -1 to -0.25.
  EXPECT_GT(after.front() - after.back(), 0.08);
  EXPECT_NEAR(eye.adaptation_log(), -1.0 + 0.75 * 1.0, 1e-7);
}

TEST(EyeSimulator, StepFromBrightToDarkBrightensSlowly) {
  EyeSimulator eye(test_plan());
  for (int i = 0; i < 30; ++i) mean_output(eye, 100.0f, i);
  const double first = mean_output(eye, 0.1f, 30);
  double last = first;
  for (int i = 31; i < 60; ++i) last = mean_output(eye, 0.1f, i);
  EXPECT_GT(last, first);
  EXPECT_NEAR(eye.adaptation_log(), 2.0 - 0.2 * 1.0, 1e-9);
}

TEST(EyeSimulator, StartsAdaptedToTheFirstFrame) {
  EyeSimulator eye(test_plan());
  mean_output(eye, 1000.0f, 0);
  EXPECT_NEAR(eye.adaptation_log(), 3.0, 1e-9);
}

TEST(EyeSimulator, ClosedEyesSeeDarknessAndAdaptTowardIt) {
  // Without afterimages closed eyes see black; with them, only the faint
  // afterimage of the 10 cd/m^2 scene (a few thousandths of the display).
  Settings plain = no_glare();
  plain.bleaching_afterimages = plain.adaptation_afterimages = false;
  io::SourceInfo info;
  info.width = kW;
  info.height = kH;
  info.frames_per_second = kFps;
  EyeSimulator without(compile_plan(plain, info)), with(test_plan());
  mean_output(without, 10.0f, 0);
  mean_output(with, 10.0f, 0);
  EXPECT_EQ(mean_output(without, 10.0f, 1, true), 0.0);
  // A dim scene bleaches mostly L cones: a reddish afterimage (H, Jacobs et al. 2015).
  const cv::Scalar afterimage_rgb = mean_rgb(with, 10.0f, 1, true);
  const double afterimage = std::max({afterimage_rgb[0], afterimage_rgb[1], afterimage_rgb[2]});
  EXPECT_GT(afterimage, 0.0);
  EXPECT_EQ(afterimage, afterimage_rgb[0]);
  EXPECT_LT(afterimage, 0.005);
  EXPECT_LT(with.adaptation_log(), 1.0);
  EXPECT_GT(mean_output(with, 10.0f, 2), 0.05);
}

TEST(EyeSimulator, NonFinitePixelsAreCountedAndNeverReachTheState) {
  EyeSimulator eye(test_plan());
  io::SceneFrame frame{test::constant_frame(kW, kH, {10, 10, 10}), 0.0, 0, "test"};
  frame.rgb.at<cv::Vec3f>(3, 3) = cv::Vec3f(NAN, 0, 0);
  frame.rgb.at<cv::Vec3f>(4, 4) = cv::Vec3f(INFINITY, INFINITY, INFINITY);
  FrameReport report;
  const io::DisplayFrame out = eye.process(frame, {{0.0, 1.0 / kFps, 3.0, 3.0, false}}, &report);
  EXPECT_EQ(report.nonfinite_pixels, 2);
  EXPECT_TRUE(std::isfinite(eye.adaptation_log()));
  EXPECT_TRUE(cv::checkRange(out.linear));
}

}  // namespace
}  // namespace eyestream::pipeline
