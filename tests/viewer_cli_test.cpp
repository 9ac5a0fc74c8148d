// The viewer profile and the PSF models as a user drives them: flags, the
// config file, the plan, and the psf command.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/exr_file.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

class ViewerCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new test::ScratchDir;
    ASSERT_EQ(test::run_eyestream("sample headlights -o " + (*scene_ / "h") + " --width 96 --height 54 --duration 0.1")
                  .exit_code,
              0);
  }
  static void TearDownTestSuite() { delete scene_; }
  static std::string run(const std::string& options) {
    return "run -i " + (*scene_ / "h/frames/%05d.exr") + " -g " + (*scene_ / "h/gaze.csv") + " " + options;
  }
  static test::ScratchDir* scene_;
  test::ScratchDir out_;
};

test::ScratchDir* ViewerCli::scene_ = nullptr;

TEST_F(ViewerCli, TheViewerProfileComesFromFlagsAndTheConfigFile) {
  auto r = test::run_eyestream(run("-o " + (out_ / "a.mp4") +
                                   " --viewer-age 70 --psf-model cie --viewer-pigmentation 1.2 --viewer-glasses "
                                   "--viewer-haze 0.1 --pupil-model watson-yellott --print-plan"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("CIE 146 scatter with Vos core and halo with flare lines"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("viewer = age 70 years, pigmentation 1.2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("glasses, haze 0.1, pupil Watson-Yellott"), std::string::npos) << r.output;
  {
    std::ofstream config(out_ / "viewer.json");
    config << R"({"viewer-age": 80, "viewer-seed": 7, "flare-lines": false})";
  }
  r = test::run_eyestream(run("-o " + (out_ / "a.mp4") + " --config " + (out_ / "viewer.json") + " --print-plan"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("viewer = age 80 years, haze 0, pupil Moon-Spencer, flare-line seed 7"), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("with flare lines"), std::string::npos) << r.output;
}

TEST_F(ViewerCli, OutOfRangeViewerValuesAreRefusedNamingTheParameter) {
  for (const char* bad : {"--viewer-pigmentation 2", "--viewer-haze 0.9", "--pupil-model round"}) {
    const auto r = test::run_eyestream(run("-o " + (out_ / "b.mp4") + " " + bad));
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.output.find(std::string(bad).substr(2, std::string(bad).find(' ') - 2)), std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(out_ / "b.mp4"));
  }
}

TEST_F(ViewerCli, EveryModelRunsAndThePsfCommandWritesEachKernel) {
  for (const char* model : {"vos", "cie", "gaussian"}) {
    const std::string out = out_ / (std::string(model) + "/%05d.exr");
    ASSERT_EQ(test::run_eyestream(run("-o " + out + " --psf-model " + model)).exit_code, 0) << model;
    const auto r = test::run_eyestream("psf -o " + (out_ / (std::string(model) + ".exr")) +
                                       " --width 96 --height 54 --adaptation 1 --psf-model " + model);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const double sum = cv::sum(io::read_exr(out_ / (std::string(model) + ".exr"), 1 << 20).rgb)[1];
    EXPECT_GT(sum, 0.8) << model;
    EXPECT_LE(sum, 1.0 + 1e-5) << model;
  }
  // Flare lines move light within each ring: the kernel's energy stays.
  const auto r = test::run_eyestream("psf -o " + (out_ / "plain.exr") +
                                     " --width 96 --height 54 --adaptation 1 --no-flare-lines");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const double lined = cv::sum(io::read_exr(out_ / "vos.exr", 1 << 20).rgb)[1];
  const double plain = cv::sum(io::read_exr(out_ / "plain.exr", 1 << 20).rgb)[1];
  EXPECT_NEAR(lined / plain, 1.0, 1e-5);
  EXPECT_GT(cv::norm(io::read_exr(out_ / "vos.exr", 1 << 20).rgb, io::read_exr(out_ / "plain.exr", 1 << 20).rgb,
                     cv::NORM_INF),
            0.0);
}

}  // namespace
}  // namespace eyestream
