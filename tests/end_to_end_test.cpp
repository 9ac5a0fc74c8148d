// The program as a user runs it: sample, run, inspect the output.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/exr_file.hpp"
#include "io/video_probe.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

namespace fs = std::filesystem;

class EndToEnd : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new test::ScratchDir();
    const auto r = test::run_eyestream("sample night-drive -o " + scene_->path().string() +
                                       " --width 160 --height 90 --duration 1");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  static void TearDownTestSuite() {
    delete scene_;
    scene_ = nullptr;
  }
  static std::string frames() { return *scene_ / "frames/%05d.exr"; }
  static std::string gaze() { return *scene_ / "gaze.csv"; }
  static std::string inputs() { return "-i " + frames() + " -g " + gaze(); }

  static test::ScratchDir* scene_;
  test::ScratchDir out_;
};

test::ScratchDir* EndToEnd::scene_ = nullptr;

TEST_F(EndToEnd, WritesATaggedH264VideoWithTheRightFramesAndDuration) {
  const auto r = test::run_eyestream("run " + inputs() + " -o " + (out_ / "demo.mp4"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const io::VideoProbe p = io::probe_video(out_ / "demo.mp4");
  EXPECT_EQ(p.codec, "h264");
  EXPECT_EQ(p.pixel_format, "yuv420p");
  EXPECT_EQ(p.color_primaries, "bt709");
  EXPECT_EQ(p.color_transfer, "bt709");
  EXPECT_EQ(p.color_space, "bt709");
  EXPECT_EQ(p.width, 160);
  EXPECT_EQ(p.height, 90);
  EXPECT_EQ(p.frame_count, 30);
  EXPECT_NEAR(p.duration_s, 1.0, 1e-6);
  EXPECT_NEAR(p.frames_per_second, 30.0, 1e-9);
  EXPECT_NE(r.output.find("30 frames"), std::string::npos) << r.output;
  EXPECT_EQ(test::count_entries(out_.path()), 1) << "only the finished video remains";
}

TEST_F(EndToEnd, SameInputsGiveIdenticalBytesWhateverTheThreadCount) {
  for (const char* ext : {"mp4", "png"}) {
    const std::string pattern = std::string(ext) == "mp4" ? "." : "%05d.";
    const std::string a = out_ / ("a" + pattern + ext), b = out_ / ("b" + pattern + ext),
                      c = out_ / ("c" + pattern + ext);
    ASSERT_EQ(test::run_eyestream("run " + inputs() + " -o " + a + " --threads 1").exit_code, 0);
    ASSERT_EQ(test::run_eyestream("run " + inputs() + " -o " + b + " --threads 2").exit_code, 0);
    ASSERT_EQ(test::run_eyestream("run " + inputs() + " -o " + c + " --threads 2").exit_code, 0);
    for (int frame : {0, 29}) {
      const auto name = [&](const std::string& p) {
        char buf[512];
        std::snprintf(buf, sizeof(buf), p.c_str(), frame);
        return std::string(buf);
      };
      const std::string ba = test::read_bytes(name(a)), bb = test::read_bytes(name(b)), bc = test::read_bytes(name(c));
      ASSERT_FALSE(ba.empty());
      EXPECT_EQ(ba, bb) << ext << " 1 vs 2 threads";
      EXPECT_EQ(bb, bc) << ext << " two runs";
    }
  }
}

TEST_F(EndToEnd, ADifferentSeedChangesTheDither) {
  ASSERT_EQ(test::run_eyestream("run " + inputs() + " -o " + (out_ / "s0_%05d.png") + " --seed 0").exit_code, 0);
  ASSERT_EQ(test::run_eyestream("run " + inputs() + " -o " + (out_ / "s1_%05d.png") + " --seed 1").exit_code, 0);
  EXPECT_NE(test::read_bytes(out_ / "s0_00010.png"), test::read_bytes(out_ / "s1_00010.png"));
}

TEST_F(EndToEnd, ExrOutputIsDisplayLinearFloat) {
  ASSERT_EQ(test::run_eyestream("run " + inputs() + " -o " + (out_ / "lin/%05d.exr")).exit_code, 0);
  EXPECT_EQ(test::count_entries(out_.path() / "lin"), 30);
  const io::ExrImage img = io::read_exr(out_ / "lin/00000.exr", 1 << 20);
  double lo, hi;
  cv::minMaxLoc(img.rgb.reshape(1), &lo, &hi);
  EXPECT_GE(lo, 0.0);
  EXPECT_GT(hi, 0.5);  // the headlights saturate
  EXPECT_LT(cv::mean(img.rgb)[1], 0.5);
}

TEST_F(EndToEnd, MissingInputFailsWithExitCode3AndLeavesNothing) {
  const std::string missing = out_ / "nothing/%05d.exr";
  const auto r = test::run_eyestream("run -i " + missing + " -o " + (out_ / "x.mp4"));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("nothing/%05d.exr"), std::string::npos) << r.output;
  EXPECT_EQ(test::count_entries(out_.path()), 0);
}

TEST_F(EndToEnd, BadGazeLineFailsNamingTheLineAndLeavesNothing) {
  std::ofstream(out_ / "g.csv") << "t,x,y\n0,1,1\n0.1,oops,2\n";
  const auto r = test::run_eyestream("run -i " + frames() + " -g " + (out_ / "g.csv") + " -o " + (out_ / "v.mp4"));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("g.csv:3"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out_ / "v.mp4"));
}

TEST_F(EndToEnd, BadOptionsFailWithExitCode2NamingTheOption) {
  auto r = test::run_eyestream("run " + inputs() + " -o " + (out_ / "v.mp4") + " --crf 90");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--crf"), std::string::npos) << r.output;
  r = test::run_eyestream("run " + inputs() + " -o " + (out_ / "v.mp4") + " --no-such-option 1");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = test::run_eyestream("run " + inputs() + " -o " + (out_ / "v.avi"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(test::count_entries(out_.path()), 0);
}

TEST_F(EndToEnd, OutputOverAnInputIsRefusedAndTheInputKept) {
  fs::copy_file(*scene_ / "frames/00000.exr", out_ / "in_00000.exr");
  const std::string before = test::read_bytes(out_ / "in_00000.exr");
  const auto r = test::run_eyestream("run -i " + (out_ / "in_%05d.exr") + " -o " + (out_ / "in_%05d.exr"));
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_EQ(test::read_bytes(out_ / "in_00000.exr"), before);
  EXPECT_EQ(test::count_entries(out_.path()), 1);
}

TEST_F(EndToEnd, CurvesCommandDrawsTheToneCurveFamily) {
  const auto r = test::run_eyestream("curves -o " + (out_ / "c.png") + " --plateau-high 0.5");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_GT(test::read_bytes(out_ / "c.png").size(), 1000u);
  EXPECT_EQ(test::run_eyestream("curves -o " + (out_ / "d.png") + " --plateau-high 2").exit_code, 2);
}

TEST_F(EndToEnd, QualityPresetsResolveAndExplicitOptionsWin) {
  const std::string out = out_ / "plan/v.mp4";
  auto r = test::run_eyestream("run " + inputs() + " -o " + out + " --quality fast --print-plan");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("glare-engine = split"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("glare-tail-factor = 4"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("state-resolution = 0.25"), std::string::npos);
  EXPECT_NE(r.output.find("stages = "), std::string::npos);
  EXPECT_NE(r.output.find("skipping = on"), std::string::npos);
  r = test::run_eyestream("run " + inputs() + " -o " + out + " --quality fast --no-skip --print-plan");
  EXPECT_NE(r.output.find("skipping = off"), std::string::npos) << r.output;
  r = test::run_eyestream("run " + inputs() + " -o " + out +
                          " --quality reference --state-resolution 0.5 --print-plan");
  EXPECT_NE(r.output.find("precision = double"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("state-resolution = 0.5"), std::string::npos) << "the explicit option wins";
  EXPECT_FALSE(fs::exists(out_ / "plan")) << "printing the plan writes nothing";
  EXPECT_EQ(test::run_eyestream("run " + inputs() + " -o " + out + " --quality turbo").exit_code, 2);
}

TEST_F(EndToEnd, HelpListsEveryOptionWithUnitDefaultAndRange) {
  const auto r = test::run_eyestream("run --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* s : {"--adapt-rate-up", "log10 units/s", "default 0.75", "0 to 1000", "--fov-deg", "--gaze",
                        "--scale", "--fps", "--skip-missing", "--config", "--threads", "--seed", "--crf"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s;
}

}  // namespace
}  // namespace eyestream
