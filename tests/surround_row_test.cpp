// The surround's light in a frame row (pipeline/eye/surround_row.hpp)
// against the formula written out here per pixel and channel.
#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/core.hpp>
#include <vector>

#include "pipeline/eye/surround_row.hpp"

namespace eyestream::pipeline {
namespace {

TEST(SurroundRow, IsTheSurroundTimesThePsfShareOutsideTheFrame) {
  const int cols = 601;  // more than two of the function's chunks, and a part one
  cv::RNG rng(7);
  cv::Mat coloured(1, cols, CV_32FC3), grey(1, cols, CV_32F), other(1, cols, CV_32FC3), base(1, cols, CV_32FC3);
  rng.fill(coloured, cv::RNG::UNIFORM, 0.0, 0.6);
  rng.fill(grey, cv::RNG::UNIFORM, 0.0, 0.5);
  rng.fill(other, cv::RNG::UNIFORM, 0.0, 0.8);
  rng.fill(base, cv::RNG::UNIFORM, 0.0, 10.0);
  const std::array<float, 4> weights = {0.3f, 0.5f, 0.9f, 0.7f};
  const cv::Vec3f kept(0.1f, 0.2f, 0.05f);
  const float s = 3.5f;
  // Components: coloured, grey, coloured; some pixels' shares exceed 1
  // (no light from outside there).
  SurroundShares shares;
  shares.count = 3;
  shares.maps = {coloured.ptr<float>(), grey.ptr<float>(), other.ptr<float>(), nullptr};
  shares.strides = {3, 1, 3, 0};
  cv::Mat got = base.clone();
  add_surround_row(shares, weights, kept, s, got.ptr<float>(), cols);
  int clipped = 0;
  for (int x = 0; x < cols; ++x)
    for (int k = 0; k < 3; ++k) {
      const double inside = double(kept[k]) + weights[0] * double(coloured.at<cv::Vec3f>(x)[k]) +
                            weights[1] * double(grey.at<float>(x)) + weights[2] * double(other.at<cv::Vec3f>(x)[k]);
      clipped += inside > 1.0;
      const double want = double(base.at<cv::Vec3f>(x)[k]) + s * std::max(0.0, 1.0 - inside);
      EXPECT_NEAR(got.at<cv::Vec3f>(x)[k], want, 1e-5 * std::max(1.0, want)) << "x " << x << ", channel " << k;
    }
  EXPECT_GT(clipped, 0) << "the test reaches the clip";
  // One map: weight 1 whatever the weights say.
  SurroundShares one;
  one.count = 1;
  one.maps = {grey.ptr<float>(), nullptr, nullptr, nullptr};
  one.strides = {1, 0, 0, 0};
  cv::Mat single = base.clone();
  add_surround_row(one, weights, cv::Vec3f(0, 0, 0), s, single.ptr<float>(), cols);
  for (int x = 0; x < cols; ++x)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(single.at<cv::Vec3f>(x)[k], base.at<cv::Vec3f>(x)[k] + s * (1.0 - grey.at<float>(x)), 1e-5 * 20)
          << "one grey map, x " << x << ", channel " << k;
}

}  // namespace
}  // namespace eyestream::pipeline
