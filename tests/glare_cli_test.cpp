// Glare as a user drives it from the command line.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/exr_file.hpp"
#include "samples/headlights.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

TEST(GlareCli, PsfCommandWritesTheKernelAPictureAndItsEnergies) {
  test::ScratchDir dir;
  const auto r = test::run_eyestream("psf -o " + (dir / "k.exr") + " --width 96 --height 54 --adaptation -3");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("energy within 0.05 deg"), std::string::npos);
  EXPECT_NE(r.output.find("beyond"), std::string::npos);
  const io::ExrImage k = io::read_exr(dir / "k.exr", 1 << 20);
  EXPECT_EQ(k.rgb.cols, 2 * 96 - 1);
  const double sum = cv::sum(k.rgb)[1];
  EXPECT_GT(sum, 0.8) << "most of the PSF's energy is within a 96x54 frame's reach";
  EXPECT_LT(sum, 1.0) << "not all: the far tail leaves the frame";
  EXPECT_TRUE(std::filesystem::exists(dir / "k.png"));
}

TEST(GlareCli, OlderViewerSeesMoreVeilOnThePedestrian) {
  test::ScratchDir dir;
  ASSERT_EQ(
      test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 192 --height 108 --duration 0.2").exit_code,
      0);
  const std::string in = "-i " + (dir / "h/frames/%05d.exr") + " -g " + (dir / "h/gaze.csv");
  ASSERT_EQ(test::run_eyestream("run " + in + " -o " + (dir / "young/%05d.exr") + " --viewer-age 25").exit_code, 0);
  ASSERT_EQ(test::run_eyestream("run " + in + " -o " + (dir / "old/%05d.exr") + " --viewer-age 75").exit_code, 0);
  ASSERT_EQ(test::run_eyestream("run " + in + " -o " + (dir / "none/%05d.exr") + " --no-glare").exit_code, 0);
  const cv::Rect target = samples::headlights_target({192, 108});
  const cv::Point beside(target.x + target.width / 2, target.y - 4);
  auto at = [&](const std::string& name) { return io::read_exr(dir / (name + "/00005.exr"), 1 << 20).rgb; };
  // Contrast of the pedestrian against the road just above it, on the display.
  auto contrast = [&](const cv::Mat& img) {
    const double t = cv::mean(img(target))[1], b = img.at<cv::Vec3f>(beside)[1];
    return (t - b) / b;
  };
  const double none = contrast(at("none")), young = contrast(at("young")), old = contrast(at("old"));
  EXPECT_GT(none, young) << "the veil lowers the target's contrast";
  EXPECT_GT(young, old) << "more for an older eye";
}

}  // namespace
}  // namespace eyestream
