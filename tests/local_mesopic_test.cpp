// Local mesopic colour: cones see a bright light whatever the viewer's
// global adaptation, so at night a red, green or amber light keeps its hue
// and the lenticular halo keeps its colour order (blue inside red), while
// dim surfaces still drift to the scotopic purple (mesopic_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "pipeline/eye/eye_simulator.hpp"
#include "tests/test_support.hpp"

namespace eyestream::pipeline {
namespace {

constexpr int kW = 320, kH = 180;
constexpr double kFps = 30.0;
constexpr float kRoad = 0.003f;

// CIELAB hue angle (deg) of linear Rec.709 RGB, scaled so its largest
// channel is 1 (the hue of the colour, not of its clipping).
double hue_deg(const cv::Vec3f& rgb) {
  const double m = std::max({rgb[0], rgb[1], rgb[2], 1e-12f});
  const double r = rgb[0] / m, g = rgb[1] / m, b = rgb[2] / m;
  const double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.9505, y = 0.2126 * r + 0.7152 * g + 0.0722 * b,
               z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.089;
  const auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; };
  const double a = 500 * (f(x) - f(y)), bb = 200 * (f(y) - f(z));
  return std::atan2(bb, a) * 180.0 / M_PI;
}

double hue_difference(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

// The display-linear frame after `seconds` of watching `scene` with the gaze
// at (gx, gy); the adaptation level is returned in *adaptation.
cv::Mat watch(const cv::Mat& scene, double gx, double gy, double seconds, double* adaptation, Settings s = {}) {
  EyeSimulator eye(test::plan_for(s, kW, kH, kFps));
  cv::Mat out;
  for (int i = 0; i < int(seconds * kFps); ++i) {
    const double t0 = i / kFps, t1 = (i + 1) / kFps;
    out = eye.process({scene, t0, i, "test"}, {{t0, t1, gx, gy, false}}).linear;
  }
  *adaptation = eye.adaptation_log();
  return out;
}

TEST(LocalMesopic, ColouredLightsKeepTheirHueOnADarkRoad) {
  // 1000 cd/m^2 lights on a 0.003 cd/m^2 road, the viewer adapted to the road.
  const cv::Vec3f colours[3] = {{1, 0, 0}, {0, 1, 0}, {1, 0.45f, 0}};  // red, green, amber
  const char* names[3] = {"red", "green", "amber"};
  cv::Mat scene = test::constant_frame(kW, kH, {kRoad, kRoad, kRoad});
  for (int i = 0; i < 3; ++i) {
    const cv::Vec3f c = colours[i] * (1000.0f / (0.2126f * colours[i][0] + 0.7152f * colours[i][1] + 0.0722f * colours[i][2]));
    cv::circle(scene, {80 + 80 * i, 60}, 3, cv::Scalar(c[0], c[1], c[2]), cv::FILLED);
  }
  double a = 0;
  const cv::Mat out = watch(scene, 160, 150, 1.0, &a);
  EXPECT_LT(a, -1.0) << "the viewer is adapted to the dark road";
  for (int i = 0; i < 3; ++i) {
    const cv::Vec3f shown = out.at<cv::Vec3f>(60, 80 + 80 * i);
    EXPECT_LT(hue_difference(hue_deg(shown), hue_deg(colours[i])), 15.0)
        << names[i] << ": shown " << shown << ", hue " << hue_deg(shown) << " vs " << hue_deg(colours[i]);
  }
  // By the adaptation level alone (the published model) the red light has
  // no scotopic luminance of its own: it shows the scotopic purple.
  Settings global;
  global.mesopic_colour.local_sigma_deg = 0.0;
  const cv::Mat old = watch(scene, 160, 150, 1.0, &a, global);
  EXPECT_GT(hue_difference(hue_deg(old.at<cv::Vec3f>(60, 80)), hue_deg(colours[0])), 30.0);
}

// With --acuity-pyramid-from set (fast: 1.2 px) a low-pass at least that
// wide runs on the frame reduced by a power of two and rho is read back
// bilinearly: the lights keep the colours the full-resolution low-pass
// gives them.
TEST(LocalMesopic, HeldReducedTheLowPassKeepsTheLightsColours) {
  const cv::Vec3f colours[3] = {{1, 0, 0}, {0, 1, 0}, {1, 0.45f, 0}};
  cv::Mat scene = test::constant_frame(kW, kH, {kRoad, kRoad, kRoad});
  for (int i = 0; i < 3; ++i) {
    const cv::Vec3f c = colours[i] * (1000.0f / (0.2126f * colours[i][0] + 0.7152f * colours[i][1] + 0.0722f * colours[i][2]));
    cv::circle(scene, {80 + 80 * i, 60}, 3, cv::Scalar(c[0], c[1], c[2]), cv::FILLED);
  }
  Settings full;
  full.mesopic_colour.local_sigma_deg = 0.5;
  full.acuity.pyramid_from_px = 0.0;
  const double sigma_px = 0.5 * test::plan_for(full, kW, kH).pixels_per_degree;
  ASSERT_GE(sigma_px, 3.0) << "wide enough to be reduced by 4";
  Settings reduced = full;
  reduced.acuity.pyramid_from_px = 1.5;
  reduced.acuity.noise_gain = full.acuity.noise_gain;
  double a = 0, b = 0;
  const cv::Mat exact = watch(scene, 160, 150, 1.0, &a, full), held = watch(scene, 160, 150, 1.0, &b, reduced);
  EXPECT_GT(cv::norm(exact, held, cv::NORM_INF), 0.0) << "the reduced path ran";
  for (int i = 0; i < 3; ++i) {
    const cv::Vec3f e = exact.at<cv::Vec3f>(60, 80 + 80 * i), h = held.at<cv::Vec3f>(60, 80 + 80 * i);
    EXPECT_LT(hue_difference(hue_deg(h), hue_deg(colours[i])), 15.0) << i << ": " << h;
    EXPECT_LT(hue_difference(hue_deg(h), hue_deg(e)), 3.0) << i << ": " << h << " against " << e;
  }
}

TEST(LocalMesopic, TheHaloKeepsItsColourOrderWhenDarkAdapted) {
  cv::Mat scene = test::constant_frame(kW, kH, {kRoad, kRoad, kRoad});
  cv::circle(scene, {160, 90}, 2, cv::Scalar::all(1e4), cv::FILLED);
  Settings s;
  s.flare_lines = false;  // the halo's radial profile alone
  s.glare_engine = "exact";
  double a = 0;
  const cv::Mat out = watch(scene, 20, 20, 1.0, &a, s);
  const double ppd = test::plan_for(s, kW, kH).pixels_per_degree;
  EXPECT_LT(a, -1.0) << "dark-adapted";
  // R/B along the ring's inner (2.3 deg) and outer (4.0 deg) edges.
  const auto r_over_b = [&](double deg) {
    const cv::Vec3f v = out.at<cv::Vec3f>(90, 160 + int(std::lround(deg * ppd)));
    return v[0] / v[2];
  };
  const double order = r_over_b(4.0) / r_over_b(2.3);
  EXPECT_GT(order, 2.0) << "R/B outer over inner: " << order;
  // Colour by the adaptation level alone (the published model) repaints it.
  s.mesopic_colour.local_sigma_deg = 0.0;
  const cv::Mat global = watch(scene, 20, 20, 1.0, &a, s);
  const cv::Vec3f inner = global.at<cv::Vec3f>(90, 160 + int(std::lround(2.3 * ppd))),
                  outer = global.at<cv::Vec3f>(90, 160 + int(std::lround(4.0 * ppd)));
  EXPECT_LT((outer[0] / outer[2]) / (inner[0] / inner[2]), 1.5);
}

}  // namespace
}  // namespace eyestream::pipeline
