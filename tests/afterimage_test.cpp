// The afterimage claims of Jacobs et al. 2015 sec. 2.2 (docs/model.md), through the
// whole eye simulator.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "pipeline/eye/eye_simulator.hpp"
#include "tests/test_support.hpp"

namespace eyestream::pipeline {
namespace {

constexpr int kW = 96, kH = 54;
constexpr double kFps = 60.0;

struct Viewer {
  explicit Viewer(Settings settings = {}) : eye(make_plan(settings)) {}
  static Plan make_plan(Settings s) {
    io::SourceInfo info;
    info.width = kW;
    info.height = kH;
    info.frames_per_second = kFps;
    return compile_plan(s, info);
  }
  // Shows `rgb` for one frame interval with the gaze at (x, y).
  cv::Mat see(const cv::Mat& rgb, double x = kW / 2.0, double y = kH / 2.0, bool closed = false) {
    io::SceneFrame f{rgb, time, frame, "test"};
    ++frame;
    const double t0 = time;
    time += dt;
    return eye.process(f, {{t0, time, x, y, closed}}).linear;
  }
  EyeSimulator eye;
  std::int64_t frame = 0;
  double time = 0.0, dt = 1.0 / kFps;
};

// Full-resolution retina state, optics off: these tests look at the
// photoreceptors alone (a flash's glare veil would bleach the surround).
Settings reference_settings() {
  Settings s;
  s.state_sites_per_pixel = 1.0;
  s.state_least_sites_per_deg = 0.0;  // the resolution a test sets, never raised
  s.glare = false;
  return s;
}

cv::Mat flash_frame(float luminance) {
  cv::Mat f = test::constant_frame(kW, kH, {0, 0, 0});
  cv::circle(f, cv::Point(kW / 2, kH / 2), 12, cv::Scalar::all(luminance), cv::FILLED);
  return f;
}

// Centroid of an image's green channel.
cv::Point2d centroid(const cv::Mat& rgb) {
  cv::Mat g;
  cv::extractChannel(rgb, g, 1);
  const cv::Moments m = cv::moments(g);
  return {m.m10 / m.m00, m.m01 / m.m00};
}

double hue_deg(const cv::Vec3f& rgb) {
  const double h = std::atan2(std::sqrt(3.0) * (rgb[1] - rgb[2]), 2.0 * rgb[0] - rgb[1] - rgb[2]) * 180.0 / M_PI;
  return h < 0 ? h + 360.0 : h;
}

// Shows a 1/8 s flash (the frames starting in [0, 0.125) s: 8 at 60 fps)
// and returns the colour at its centre every frame of the darkness after.
std::vector<cv::Vec3f> flash_then_darkness(float luminance, double seconds_after, Settings s = reference_settings()) {
  Viewer v(s);
  const cv::Mat dark = test::constant_frame(kW, kH, {0, 0, 0});
  for (int i = 0; i < 30; ++i) v.see(dark);
  for (int i = 0; i < 8; ++i) v.see(flash_frame(luminance));
  std::vector<cv::Vec3f> after;
  for (int i = 0; i < int(seconds_after * kFps); ++i) after.push_back(v.see(dark).at<cv::Vec3f>(kH / 2, kW / 2));
  return after;
}

TEST(Afterimages, LongConstantStimulusShowsExactlyThePlainToneCurve) {
  // A patterned scene: the state starts at rest for it and stays there, so
  // both afterimage terms vanish and the output equals the output with
  // afterimages switched off, bit for bit.
  cv::Mat scene = test::constant_frame(kW, kH, {20, 20, 20});
  cv::rectangle(scene, cv::Rect(10, 10, 30, 20), cv::Scalar(5000, 3000, 1000), cv::FILLED);
  cv::circle(scene, cv::Point(70, 30), 8, cv::Scalar(1, 2, 40), cv::FILLED);
  Settings off = reference_settings();
  off.bleaching_afterimages = off.adaptation_afterimages = false;
  Viewer with(reference_settings()), without(off);
  for (int i = 0; i < 120; ++i) {
    const cv::Mat a = with.see(scene), b = without.see(scene);
    ASSERT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0) << "frame " << i;
  }
}

TEST(Afterimages, StateConvergesToRestAfterTheStimulusChanges) {
  // After a change, the afterimage terms decay: 60 s later the output is
  // within 1e-4 of the plain tone curve (stated tolerance).
  cv::Mat first = test::constant_frame(kW, kH, {20, 20, 20});
  cv::rectangle(first, cv::Rect(30, 15, 30, 20), cv::Scalar(1e4, 1e4, 1e4), cv::FILLED);
  const cv::Mat second = test::constant_frame(kW, kH, {20, 20, 20});
  Settings off = reference_settings();
  off.bleaching_afterimages = off.adaptation_afterimages = false;
  Viewer with(reference_settings()), without(off);
  for (int i = 0; i < 120; ++i) with.see(first), without.see(first);
  // The updates are exact for any step, so 0.25 s frames cover a minute fast.
  with.dt = without.dt = 0.25;
  double difference = cv::norm(with.see(second), without.see(second), cv::NORM_INF);
  EXPECT_GT(difference, 1e-3) << "an afterimage right after the change";
  for (int i = 0; i < 240; ++i) difference = cv::norm(with.see(second), without.see(second), cv::NORM_INF);
  EXPECT_LT(difference, 1e-4);
}

// Jacobs et al. 2015 figs. 4, 5 and 7: a 1e7 cd/m^2 neutral flash leaves an
// afterimage that starts cyan, turns green as the S cones recover, and ends
// magenta as only the L cones stay bleached, fading within seconds.
TEST(Afterimages, BrightFlashAfterimageGoesCyanThenGreenThenMagentaAndFades) {
  const auto colours = flash_then_darkness(1e7f, 6.0);
  auto hue_at = [&](double t) { return hue_deg(colours[size_t(t * kFps)]); };
  EXPECT_NEAR(hue_at(0.02), 180.0, 30.0) << "cyan at first";
  EXPECT_NEAR(hue_at(0.6), 120.0, 30.0) << "green next";
  EXPECT_NEAR(hue_at(2.5), 320.0, 35.0) << "magenta last";
  // The phases come in that order: first frame of each.
  int first_green = -1, first_magenta = -1;
  for (size_t k = 0; k < colours.size(); ++k) {
    const double h = hue_deg(colours[k]);
    if (first_green < 0 && std::abs(h - 120.0) < 30.0) first_green = int(k);
    if (first_green >= 0 && first_magenta < 0 && std::abs(h - 320.0) < 35.0) first_magenta = int(k);
  }
  EXPECT_GT(first_green, 0);
  EXPECT_GT(first_magenta, first_green);
  const float peak = cv::norm(colours.front(), cv::NORM_INF);
  EXPECT_GT(peak, 0.02f);
  EXPECT_LT(cv::norm(colours.back(), cv::NORM_INF), 0.1f * peak) << "faded after 6 s";
}

// Jacobs et al. 2015 fig. 5: dimmer flashes (1e3-1e4) start pink/magenta, brighter
// ones (1e5 and up) green or cyan; the transition lies between 1e4 and 1e5.
TEST(Afterimages, DimFlashesStartMagentaAndTheGreenOnsetLiesBetween1e4And1e5) {
  auto start_hue = [](float luminance) { return hue_deg(flash_then_darkness(luminance, 0.05).front()); };
  for (float l : {1e3f, 1e4f}) {
    const double h = start_hue(l);
    EXPECT_TRUE(h > 280.0 || h < 20.0) << l << " cd/m^2 starts at hue " << h;
  }
  for (float l : {1e5f, 1e6f}) {
    const double h = start_hue(l);
    EXPECT_TRUE(h > 90.0 && h < 210.0) << l << " cd/m^2 starts at hue " << h;
  }
}

// Jacobs et al. 2015 fig. 9: after fixating a bright patch, a uniform grey shows a
// darker patch there (negative afterimage); a blue patch leaves a yellowish one.
TEST(Afterimages, FixatedPatchesLeaveNegativeAndOpponentAfterimages) {
  cv::Mat patches = test::constant_frame(kW, kH, {100, 100, 100});
  const cv::Rect white(12, 17, 20, 20), blue(64, 17, 20, 20);
  patches(white).setTo(cv::Scalar(1000, 1000, 1000));
  patches(blue).setTo(cv::Scalar(0, 0, 100 / 0.0722));
  const cv::Mat grey = test::constant_frame(kW, kH, {100, 100, 100});
  Viewer v(reference_settings());
  for (int i = 0; i < int(10 * kFps); ++i) v.see(patches);
  const cv::Mat after = v.see(grey);
  const cv::Vec3f surround = after.at<cv::Vec3f>(5, kW / 2);
  const cv::Vec3f at_white = after.at<cv::Vec3f>(27, 22), at_blue = after.at<cv::Vec3f>(27, 74);
  auto luminance = [](const cv::Vec3f& p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; };
  EXPECT_LT(luminance(at_white), 0.97 * luminance(surround)) << "negative afterimage of the white patch";
  EXPECT_NEAR(surround[0], surround[2], 1e-4) << "the surround stays neutral";
  EXPECT_GT(at_blue[0] / at_blue[2], 1.02) << "yellowish: blue weakened against red";
  EXPECT_GT(at_blue[1] / at_blue[2], 1.02) << "yellowish: blue weakened against green";
}

// docs/model.md: afterimages are locked to the retina. After a flash, a gaze
// jump of N pixels moves the afterimage N pixels on the display, unsmeared
// (on an equidistant frame, whose pixels all subtend one angle).
TEST(Afterimages, AfterimageMovesWithTheGazeWithoutSmearing) {
  Settings s = reference_settings();
  s.geometry.projection = "equidistant";
  Viewer v(s);
  const cv::Mat dark = test::constant_frame(kW, kH, {0, 0, 0});
  for (int i = 0; i < 8; ++i) v.see(flash_frame(1e7f));
  const cv::Mat before = v.see(dark);
  const int n = 17;
  const cv::Mat moved = v.see(dark, kW / 2.0 + n, kH / 2.0);
  const cv::Mat back = v.see(dark);
  // Compare the moved afterimage with the one before shifted by n pixels;
  // one frame of decay (1/60 s) separates them, so compare shapes.
  cv::Mat shifted = cv::Mat::zeros(before.size(), before.type());
  before(cv::Rect(0, 0, kW - n, kH)).copyTo(shifted(cv::Rect(n, 0, kW - n, kH)));
  const double scale = cv::norm(moved) / cv::norm(shifted);
  EXPECT_GT(scale, 0.9);
  EXPECT_LT(cv::norm(moved, shifted * scale, cv::NORM_INF), 0.02 * cv::norm(moved, cv::NORM_INF));
  const cv::Point2d c_before = centroid(before), c_moved = centroid(moved), c_back = centroid(back);
  EXPECT_NEAR(c_moved.x - c_before.x, n, 0.05);
  EXPECT_NEAR(c_moved.y, c_before.y, 0.05);
  EXPECT_NEAR(c_back.x, c_before.x, 0.05) << "returning the gaze returns the afterimage";
}

TEST(Afterimages, EachKindCanBeSwitchedOff) {
  Settings no_bleach = reference_settings();
  no_bleach.bleaching_afterimages = false;
  const auto colours = flash_then_darkness(1e7f, 0.2, no_bleach);
  EXPECT_EQ(cv::norm(colours.back(), cv::NORM_INF), 0.0) << "no bleaching afterimage in darkness";
  EXPECT_GT(cv::norm(flash_then_darkness(1e7f, 0.2).back(), cv::NORM_INF), 0.01);
}

TEST(Afterimages, ReducedStateResolutionKeepsTheFlightOfColours) {
  Settings half = reference_settings();
  half.state_sites_per_pixel = 0.5;
  const auto reduced = flash_then_darkness(1e7f, 3.0, half), full = flash_then_darkness(1e7f, 3.0);
  for (double t : {0.02, 0.6, 2.5}) {
    const size_t k = size_t(t * kFps);
    EXPECT_NEAR(hue_deg(reduced[k]), hue_deg(full[k]), 10.0) << t;
    EXPECT_NEAR(cv::norm(reduced[k]), cv::norm(full[k]), 0.1 * cv::norm(full[k])) << t;
  }
}

TEST(Afterimages, ExtremeFramesKeepTheStateBoundedAndTheOutputFinite) {
  cv::Mat extreme(kH, kW, CV_32FC3);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      extreme.at<cv::Vec3f>(y, x) = cv::Vec3f::all(float(std::pow(10.0, -6 + 15.0 * x / kW)));
  extreme.at<cv::Vec3f>(3, 3) = cv::Vec3f(NAN, INFINITY, -INFINITY);
  Viewer v(reference_settings());
  for (int i = 0; i < 20; ++i) {
    const cv::Mat out = v.see(i % 2 ? extreme : test::constant_frame(kW, kH, {0, 0, 0}), 5.0 + 4 * i, 20.0);
    ASSERT_TRUE(cv::checkRange(out)) << i;
    double lo, hi;
    cv::minMaxLoc(v.eye.retina().state().bleached().reshape(1), &lo, &hi);
    ASSERT_GE(lo, 0.0);
    ASSERT_LE(hi, 1.0);
    cv::minMaxLoc(v.eye.retina().state().deficit().reshape(1), &lo, &hi);
    ASSERT_GE(lo, 0.0);
    ASSERT_LE(hi, v.eye.retina().state().calcium_max());
  }
}

}  // namespace
}  // namespace eyestream::pipeline
