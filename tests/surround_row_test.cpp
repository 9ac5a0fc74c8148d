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

TEST(SurroundRow, ThreeGreySharesInterleavedGiveWhatThreeSeparateMapsGive) {
  // The glare stage's core, inner and outer shares come from one pass, one
  // a channel: read interleaved, they give the bytes the three split maps
  // gave, with a coloured halo after them (and against the formula).
  const int cols = 601;
  cv::RNG rng(11);
  cv::Mat triple(1, cols, CV_32FC3), halo(1, cols, CV_32FC3), base(1, cols, CV_32FC3);
  rng.fill(triple, cv::RNG::UNIFORM, 0.0, 0.8);
  rng.fill(halo, cv::RNG::UNIFORM, 0.0, 0.3);
  rng.fill(base, cv::RNG::UNIFORM, 0.0, 10.0);
  std::vector<cv::Mat> split;
  cv::split(triple, split);
  const std::array<float, 4> weights = {0.6f, 0.25f, 0.4f, 0.8f};
  const cv::Vec3f kept(0.05f, 0.1f, 0.02f);
  const float s = 2.5f;
  SurroundShares apart;
  apart.count = 4;
  apart.maps = {split[0].ptr<float>(), split[1].ptr<float>(), split[2].ptr<float>(), halo.ptr<float>()};
  apart.strides = {1, 1, 1, 3};
  SurroundShares together;
  together.triple = triple.ptr<float>();
  together.count = 1;
  together.maps = {halo.ptr<float>(), nullptr, nullptr, nullptr};
  together.strides = {3, 0, 0, 0};
  cv::Mat want = base.clone(), got = base.clone();
  add_surround_row(apart, weights, kept, s, want.ptr<float>(), cols);
  add_surround_row(together, weights, kept, s, got.ptr<float>(), cols);
  int clipped = 0;
  for (int x = 0; x < cols; ++x)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(got.at<cv::Vec3f>(x)[k], want.at<cv::Vec3f>(x)[k]) << "x " << x << ", channel " << k;
      const cv::Vec3f t = triple.at<cv::Vec3f>(x);
      const double inside = double(kept[k]) + weights[0] * double(t[0]) + weights[1] * double(t[1]) +
                            weights[2] * double(t[2]) + weights[3] * double(halo.at<cv::Vec3f>(x)[k]);
      clipped += inside > 1.0;
      const double formula = double(base.at<cv::Vec3f>(x)[k]) + s * std::max(0.0, 1.0 - inside);
      EXPECT_NEAR(got.at<cv::Vec3f>(x)[k], formula, 1e-5 * std::max(1.0, formula)) << "x " << x << ", channel " << k;
    }
  EXPECT_GT(clipped, 0) << "the test reaches the clip";
  // The program's usual case: a grey halo after the triple, onto rows of
  // 0 (no rounding of the sum hides a difference).
  cv::Mat grey_halo(1, cols, CV_32F);
  rng.fill(grey_halo, cv::RNG::UNIFORM, 0.0, 0.3);
  apart.maps[3] = grey_halo.ptr<float>(), apart.strides[3] = 1;
  together.maps[0] = grey_halo.ptr<float>(), together.strides[0] = 1;
  cv::Mat want0 = cv::Mat::zeros(1, cols, CV_32FC3), got0 = want0.clone();
  add_surround_row(apart, weights, kept, s, want0.ptr<float>(), cols);
  add_surround_row(together, weights, kept, s, got0.ptr<float>(), cols);
  EXPECT_EQ(cv::norm(got0, want0, cv::NORM_INF), 0.0) << "a grey halo after the triple";
  EXPECT_GT(cv::norm(got0, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace eyestream::pipeline
