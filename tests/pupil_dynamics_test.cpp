// The pupil follows the field's luminance (Moon and Spencer 1944), not the
// patch at the gaze, with its own time course: fast constriction, slow
// dilation (Ellis 1981), the same at any frame rate.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "glare/pupil.hpp"
#include "glare/pupil_dynamics.hpp"
#include "pipeline/eye/eye_simulator.hpp"
#include "tests/test_support.hpp"

namespace eyestream::pipeline {
namespace {

constexpr int kW = 96, kH = 54;

// Watches `scene_at(t)` for `seconds` at `fps`, gaze at the centre; returns
// the report's pupil after each frame.
std::vector<double> pupil_track(const std::function<cv::Mat(double)>& scene_at, double seconds, double fps) {
  Settings s;
  s.report = "r.csv";  // the report's fields are filled
  EyeSimulator eye(test::plan_for(s, kW, kH, fps));
  std::vector<double> track;
  for (int i = 0; i < int(std::lround(seconds * fps)); ++i) {
    const double t0 = i / fps, t1 = (i + 1) / fps;
    FrameReport r;
    eye.process({scene_at(t0), t0, i, "test"}, {{t0, t1, kW / 2.0, kH / 2.0, false}}, &r);
    track.push_back(r.pupil_mm);
  }
  return track;
}

TEST(PupilDynamics, ThePupilFollowsTheFieldNotTheGazePatch) {
  // A 100 cd/m^2 field with a dark patch where the viewer looks.
  cv::Mat scene = test::constant_frame(kW, kH, {100, 100, 100});
  cv::rectangle(scene, cv::Rect(kW / 2 - 6, kH / 2 - 6, 12, 12), cv::Scalar::all(0.01), cv::FILLED);
  const double field = cv::mean(scene)[1];
  const std::vector<double> track = pupil_track([&](double) { return scene; }, 3.0, 30.0);
  EXPECT_NEAR(track.back(), glare::moon_spencer_pupil_mm(std::log10(field)), 0.02);
  EXPECT_LT(track.back(), 2.6) << "Moon-Spencer gives 2.40 mm at 100 cd/m^2; the dark patch would give 6.0";
}

TEST(PupilDynamics, ConstrictsInTenthsOfASecondAndDilatesOverSeconds) {
  const cv::Mat dark = test::constant_frame(kW, kH, {0.01f, 0.01f, 0.01f});
  const cv::Mat bright = test::constant_frame(kW, kH, {100, 100, 100});
  const double d_dark = glare::moon_spencer_pupil_mm(-2.0), d_bright = glare::moon_spencer_pupil_mm(2.0);
  const double fps = 60.0;
  // Dark for 1 s, then bright: half the way in under 0.3 s.
  const std::vector<double> up = pupil_track([&](double t) { return t < 1.0 ? dark : bright; }, 2.0, fps);
  EXPECT_NEAR(up[size_t(fps) - 1], d_dark, 1e-6) << "at rest in the dark";
  const double half = 0.5 * (d_dark + d_bright);
  EXPECT_LT(up[size_t(1.3 * fps)], half) << "constricted past half way 0.3 s after the light";
  EXPECT_GT(up[size_t(fps)], half) << "but not at once: a frame after the light, less than half way";
  // Bright for 1 s, then dark: less than half the way back after 0.8 s.
  const std::vector<double> down = pupil_track([&](double t) { return t < 1.0 ? bright : dark; }, 3.0, fps);
  EXPECT_LT(down[size_t(1.8 * fps)], half) << "dilation is slow";
  EXPECT_GT(down.back(), down[size_t(1.8 * fps)]);
}

TEST(PupilDynamics, TheTimeCourseDoesNotDependOnTheFrameRate) {
  const cv::Mat dark = test::constant_frame(kW, kH, {0.01f, 0.01f, 0.01f});
  const cv::Mat bright = test::constant_frame(kW, kH, {100, 100, 100});
  const auto scene = [&](double t) { return t < 0.5 ? bright : dark; };
  const std::vector<double> a = pupil_track(scene, 2.0, 30.0), b = pupil_track(scene, 2.0, 120.0);
  EXPECT_NEAR(a.back(), b.back(), 1e-9);
}

}  // namespace
}  // namespace eyestream::pipeline
