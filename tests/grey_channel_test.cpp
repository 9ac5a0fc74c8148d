// pipeline/eye/pixel_checks.hpp's one_channel_if_grey: a map whose three channels agree everywhere
// comes back as one channel holding channel 0's bytes; one pixel that
// differs anywhere (first, middle, last) keeps all three, the map itself.
#include "pipeline/eye/pixel_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace eyestream::pipeline {
namespace {

cv::Mat grey_map(cv::Size size) {
  cv::Mat one(size, CV_32F);
  cv::RNG(5).fill(one, cv::RNG::UNIFORM, 0.0, 1.0);
  one.at<float>(0, 1) = 0.0f;
  cv::Mat map;
  cv::merge(std::vector<cv::Mat>{one, one, one}, map);
  map.at<cv::Vec3f>(0, 1)[2] = -0.0f;  // equal to +0, as the comparison takes it
  return map;
}

TEST(GreyMap, EqualChannelsBecomeOneWithChannelZerosBytes) {
  const cv::Mat map = grey_map({37, 23});
  const cv::Mat got = one_channel_if_grey(map);
  ASSERT_EQ(got.type(), CV_32F);
  ASSERT_EQ(got.size(), map.size());
  for (int y = 0; y < map.rows; ++y)
    for (int x = 0; x < map.cols; ++x)
      ASSERT_EQ(std::memcmp(&got.at<float>(y, x), &map.at<cv::Vec3f>(y, x)[0], sizeof(float)), 0) << x << "," << y;
}

TEST(GreyMap, OneDifferingValueAnywhereKeepsTheMap) {
  for (const cv::Point at : {cv::Point(0, 0), cv::Point(18, 11), cv::Point(36, 22)})
    for (int channel : {1, 2}) {
      cv::Mat map = grey_map({37, 23});
      map.at<cv::Vec3f>(at)[channel] = std::nextafter(map.at<cv::Vec3f>(at)[0], 2.0f);
      const cv::Mat got = one_channel_if_grey(map);
      EXPECT_EQ(got.type(), CV_32FC3) << at << " channel " << channel;
      EXPECT_EQ(got.data, map.data) << "the map itself, not a copy";
    }
}

}  // namespace
}  // namespace eyestream::pipeline
