// The retina features as a user drives them from the command line.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "io/exr_file.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

TEST(RetinaCli, FlashSampleShowsAnAfterimageThatTheSwitchRemoves) {
  test::ScratchDir dir;
  const std::string scene = dir / "flash";
  ASSERT_EQ(test::run_eyestream("sample flash -o " + scene + " --width 128 --height 72 --duration 1.5").exit_code, 0);
  // Optics off: the flash's glare veil would light the whole frame.
  const std::string in = "-i " + scene + "/frames/%05d.exr -g " + scene + "/gaze.csv --no-glare";
  ASSERT_EQ(test::run_eyestream("run " + in + " -o " + (dir / "on/%05d.exr")).exit_code, 0);
  ASSERT_EQ(
      test::run_eyestream("run " + in + " -o " + (dir / "off/%05d.exr") + " --no-bleaching-afterimages").exit_code, 0);
  // Frame 30 (1.0 s) is dark, 0.375 s after the flash.
  const cv::Mat on = io::read_exr(dir / "on/00030.exr", 1 << 20).rgb,
                off = io::read_exr(dir / "off/00030.exr", 1 << 20).rgb;
  const cv::Vec3f centre = on.at<cv::Vec3f>(36, 64);
  EXPECT_GT(centre[1], 0.005f) << "a greenish afterimage at the flash";
  EXPECT_GT(centre[1], centre[0]);
  EXPECT_LT(cv::norm(off.at<cv::Vec3f>(36, 64), cv::NORM_INF), 1e-3) << "gone with --no-bleaching-afterimages";
  EXPECT_LT(cv::norm(on.at<cv::Vec3f>(2, 2), cv::NORM_INF), 1e-3) << "nothing far from the flash";
}

TEST(RetinaCli, StateOfAChosenFrameIsWrittenAsAMultiChannelExr) {
  test::ScratchDir dir;
  const std::string scene = dir / "a";
  ASSERT_EQ(test::run_eyestream("sample adaptation -o " + scene + " --width 64 --height 36 --duration 1.5 --fps 10")
                .exit_code,
            0);
  const auto r = test::run_eyestream("run -i " + scene + "/frames/%05d.exr -g " + scene + "/gaze.csv -o " +
                                     (dir / "v.mp4") + " --state-exr " + (dir / "state.exr") + " --state-frame 5");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  Imf::InputFile file((dir / "state.exr").c_str());
  int channels = 0;
  for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) ++channels;
  EXPECT_EQ(channels, 6);
  for (const char* name : {"B.L", "B.M", "B.S", "C.L", "C.M", "C.S"})
    EXPECT_NE(file.header().channels().findChannel(name), nullptr) << name;
  // The grid spans twice the frame at the default half resolution.
  const Imath::Box2i dw = file.header().dataWindow();
  EXPECT_GE(dw.max.x - dw.min.x + 1, 64);
}

}  // namespace
}  // namespace eyestream
