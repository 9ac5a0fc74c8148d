// Bad input, extremes and long runs (docs/model.md).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/exr_file.hpp"
#include "pipeline/eye/eye_simulator.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

namespace fs = std::filesystem;

TEST(Robustness, NonFinitePixelsFailOnRequestNamingFileAndFrame) {
  test::ScratchDir dir;
  cv::Mat frame = test::constant_frame(32, 18, {1, 1, 1});
  io::write_exr(dir / "f_0.exr", frame, {false, std::nullopt, 30.0});
  frame.at<cv::Vec3f>(4, 4) = cv::Vec3f(NAN, 1, 1);
  frame.at<cv::Vec3f>(5, 5) = cv::Vec3f(INFINITY, 1, 1);
  io::write_exr(dir / "f_1.exr", frame, {false, std::nullopt, 30.0});
  const std::string in = "-i " + (dir / "f_%d.exr");
  auto r = test::run_eyestream("run " + in + " -o " + (dir / "out/%05d.png") + " --bad-pixels fail");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("f_1.exr: frame 1 has 2 NaN or infinite pixels"), std::string::npos) << r.output;
  EXPECT_EQ(test::count_entries(dir.path() / "out"), 0) << "nothing left behind";
  r = test::run_eyestream("run " + in + " -o " + (dir / "out/%05d.png"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("2 non-finite pixels shown black"), std::string::npos) << r.output;
}

TEST(Robustness, UnwritableOutputFailsWithExitCode4) {
  test::ScratchDir dir;
  io::write_exr(dir / "f_0.exr", test::constant_frame(32, 18, {1, 1, 1}), {false, std::nullopt, 30.0});
  const auto r = test::run_eyestream("run -i " + (dir / "f_%d.exr") + " -o /dev/null/sub/v.mp4");
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("/dev/null/sub"), std::string::npos) << r.output;
}

// A video that ends before its container says: fail (exit 3, naming the
// file, no output), or with --on-bad-video stop, finalise what was read.
TEST(Robustness, TruncatedVideoFailsOrStopsWithWhatWasRead) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample night-drive -o " + (dir / "nd") + " --width 160 --height 90 --duration 0.5")
                .exit_code,
            0);
  auto r = test::run_eyestream("run -i " + (dir / "nd/frames") + " -o " + (dir / "full.mkv") + " --hdr10 --keyint 1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string bytes = test::read_bytes(dir / "full.mkv");
  std::ofstream(dir / "cut.mkv", std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() * 7 / 10));
  r = test::run_eyestream("run -i " + (dir / "cut.mkv") + " -o " + (dir / "a.mp4"));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("cut.mkv: ends after"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "a.mp4"));
  r = test::run_eyestream("run -i " + (dir / "cut.mkv") + " -o " + (dir / "b/%05d.png") + " --on-bad-video stop");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning"), std::string::npos) << r.output;
  const int written = test::count_entries(dir.path() / "b");
  EXPECT_GT(written, 3);
  EXPECT_LT(written, 15);
}

pipeline::Plan small_plan(int w, int h) { return test::plan_for(pipeline::Settings{}, w, h); }

// A constant scene for 100 000 frames (an hour at 30 fps, at small size):
// once adaptation and the pupil have settled (the first frame's optics
// follow the raw scene, later ones the glared retinal image), the output
// never drifts: every later frame is bit-identical. Photopic, so the
// acuity loss, which changes from frame to frame by design, is off.
TEST(Robustness, HundredThousandFramesOfAConstantSceneDoNotDrift) {
  const int w = 12, h = 8;
  pipeline::EyeSimulator eye(small_plan(w, h));
  cv::Mat scene = test::constant_frame(w, h, {50.0f, 50.0f, 50.0f});
  scene.at<cv::Vec3f>(2, 3) = cv::Vec3f(5e4f, 4e4f, 3e4f);  // a lamp above the display peak
  scene.at<cv::Vec3f>(6, 9) = cv::Vec3f(1.0f, 2.0f, 20.0f);
  cv::Mat settled;
  for (int i = 0; i < 100000; ++i) {
    const double t = i / 30.0;
    const io::SceneFrame f{scene, t, i, "constant"};
    const cv::Mat out = eye.process(f, {{t, t + 1 / 30.0, 6.0, 4.0, false}}).linear;
    if (i == 3000) {
      settled = out.clone();
    } else if (i > 3000 && (i % 997 == 0 || i == 99999)) {
      ASSERT_EQ(cv::norm(out, settled, cv::NORM_INF), 0.0) << "frame " << i;
    }
  }
  double lo, hi;
  cv::minMaxLoc(eye.retina().state().bleached().reshape(1), &lo, &hi);
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, 1.0);
}

// dt of zero, a microsecond and ten minutes between frames; one frame
// spanning 1e-6 to 1e9 cd/m^2.
TEST(Robustness, ExtremeTimeStepsAndLuminancesStayFinite) {
  const int w = 40, h = 24;
  pipeline::EyeSimulator eye(small_plan(w, h));
  cv::Mat scene(h, w, CV_32FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      scene.at<cv::Vec3f>(y, x) = cv::Vec3f::all(float(std::pow(10.0, -6.0 + 15.0 * x / (w - 1))));
  double t = 0.0;
  for (double dt : {0.0, 1e-6, 1.0 / 30, 600.0, 0.0, 1e-6, 600.0}) {
    const io::SceneFrame f{scene, t, 0, "extreme"};
    const cv::Mat out = eye.process(f, {{t, t + dt, 20.0, 12.0, false}}).linear;
    t += dt;
    ASSERT_TRUE(cv::checkRange(out)) << "dt=" << dt;
    ASSERT_TRUE(std::isfinite(eye.adaptation_log()));
    double lo, hi;
    cv::minMaxLoc(eye.retina().state().deficit().reshape(1), &lo, &hi);
    ASSERT_GE(lo, 0.0);
    ASSERT_LE(hi, eye.retina().state().calcium_max());
  }
}

}  // namespace
}  // namespace eyestream
