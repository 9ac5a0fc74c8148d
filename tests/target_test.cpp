// The visibility target: its luminance, its surround, the contrast with and
// without the veil, and the ways a target can be given wrongly.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "io/error.hpp"
#include "pipeline/eye/target_region.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

using pipeline::measure_target;
using pipeline::TargetRegion;

TEST(Target, MeansOverTheTargetAndARingAsWideAsItsSmallerSide) {
  cv::Mat lum(60, 80, CV_32F, cv::Scalar(1.0f));
  const cv::Rect target(30, 20, 4, 10);
  lum(target).setTo(2.0f);
  // Light just outside the ring (r = 4 px) must not count.
  lum(cv::Rect(30 - 5, 20, 1, 10)).setTo(100.0f);
  cv::Mat mask = cv::Mat::zeros(lum.size(), CV_8U);
  mask(target).setTo(255);
  const auto t = measure_target(lum, mask);
  ASSERT_TRUE(t);
  EXPECT_DOUBLE_EQ(t->target_cd_m2, 2.0);
  EXPECT_DOUBLE_EQ(t->background_cd_m2, 1.0);
  EXPECT_DOUBLE_EQ(t->x, 32.0);
  EXPECT_DOUBLE_EQ(t->y, 25.0);
  EXPECT_DOUBLE_EQ(pipeline::luminance_contrast(2.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(pipeline::luminance_contrast(2.0, 1.0, 0.5), 1.0 / 1.5);
  EXPECT_FALSE(measure_target(lum, cv::Mat::zeros(lum.size(), CV_8U))) << "an empty mask is no target";
  EXPECT_FALSE(measure_target(lum, cv::Mat()));
}

TEST(Target, ARectangleIsTheSameMaskEveryFrame) {
  const TargetRegion r("10,5,3,4", "", cv::Size(40, 30));
  ASSERT_TRUE(r.enabled());
  EXPECT_EQ(cv::countNonZero(r.mask(0)), 12);
  EXPECT_EQ(cv::countNonZero(r.mask(1000) != r.mask(0)), 0);
  EXPECT_FALSE(TargetRegion("", "", cv::Size(40, 30)).enabled());
}

TEST(Target, MalformedOrMisplacedRectanglesAreUsageErrors) {
  for (const char* bad : {"1,2,3", "1,2,3,4,5", "a,b,c,d", "38,5,3,4", "0,0,0,4", "-1,0,2,2"})
    EXPECT_THROW(TargetRegion(bad, "", cv::Size(40, 30)), UsageError) << bad;
  EXPECT_THROW(TargetRegion("1,1,2,2", "m.png", cv::Size(40, 30)), UsageError) << "both given";
}

TEST(Target, MaskSequencesNameTheMissingFrameOrTheWrongFile) {
  test::ScratchDir dir;
  std::filesystem::create_directories(dir.path() / "m");
  cv::Mat m = cv::Mat::zeros(30, 40, CV_8U);
  m(cv::Rect(2, 2, 5, 5)).setTo(255);
  cv::imwrite(dir / "m/00000.png", m);
  cv::imwrite(dir / "m/00001.png", m);
  const TargetRegion two("", dir / "m/%05d.png", cv::Size(40, 30));
  EXPECT_EQ(cv::countNonZero(two.mask(1)), 25);
  try {
    two.mask(2);
    FAIL() << "no mask for frame 2";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("frame 2"), std::string::npos) << e.what();
  }
  cv::imwrite(dir / "small.png", cv::Mat::zeros(10, 10, CV_8U));
  try {
    TargetRegion("", dir / "small.png", cv::Size(40, 30)).mask(0);
    FAIL() << "a mask of another size";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("small.png"), std::string::npos) << e.what();
  }
  // One file serves every frame.
  EXPECT_EQ(cv::countNonZero(TargetRegion("", dir / "m/00000.png", cv::Size(40, 30)).mask(99)), 25);
}

}  // namespace
}  // namespace eyestream
