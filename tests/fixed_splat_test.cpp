// pipeline/geometry/fixed_splat.hpp on made-up positions, against a
// bilinear splat summed here in double, pixel by pixel: pixels that step
// back, jump several columns or rows either way, sit exactly on pixel
// centres and edges or on the plane's border, over planes shorter than a
// block of rows and not a whole number of blocks; the sums (factor 1) and
// the factor's product, and the same bytes whatever the thread count.
#include "pipeline/geometry/fixed_splat.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <tuple>
#include <opencv2/core/utility.hpp>

#include "tests/bilinear_share_oracle.hpp"

namespace eyestream::pipeline {
namespace {

// The splat summed in double: each position's bilinear shares of the four
// plane pixels around it (pixel centres at integer + 0.5), those beyond
// the plane dropped, times `factor`. `reach` gets, per plane pixel, the
// sum of the values that have a share in it: the splat's shares come from
// float positions, so each can be off by a few of the position's last
// bits, times its value.
cv::Mat naive_splat(const cv::Mat& frame, const cv::Mat& positions, cv::Size plane, const cv::Mat& factor,
                    cv::Mat& reach) {
  cv::Mat sums(plane, CV_64FC3, cv::Scalar::all(0.0));
  reach = cv::Mat(plane, CV_64FC3, cv::Scalar::all(0.0));
  for (int y = 0; y < frame.rows; ++y)
    for (int x = 0; x < frame.cols; ++x) {
      const cv::Vec2f p = positions.at<cv::Vec2f>(y, x);
      const cv::Vec3d value(frame.at<cv::Vec3f>(y, x));
      test::for_each_bilinear_share(p[0] - 0.5, p[1] - 0.5, plane, [&](int i, int j, double share) {
        sums.at<cv::Vec3d>(j, i) += share * value;
        reach.at<cv::Vec3d>(j, i) += value;
      });
    }
  for (int v = 0; v < plane.height; ++v)
    for (int u = 0; u < plane.width; ++u) {
      sums.at<cv::Vec3d>(v, u) *= double(factor.at<float>(v, u));
      reach.at<cv::Vec3d>(v, u) *= double(factor.at<float>(v, u));
    }
  return sums;
}

// Positions that wander: in 4 of 14 pixels a step of 0.4-1.1 columns
// along a slowly curving row, the rest steps back, jumps of several columns and rows
// up and down, exact centres (integer + 0.5) and edges (integers), and the
// plane's borders (-0.5, width + 0.5 - a little, 0 rows), rows below the
// plane, near and as far as allowed (1e8).
cv::Mat wandering_positions(cv::Size frame, cv::Size plane, unsigned seed) {
  cv::RNG rng(seed);
  cv::Mat positions(frame, CV_32FC2);
  const float top_x = float(plane.width) + 0.5f - 1e-3f;
  for (int y = 0; y < frame.height; ++y) {
    float px = float(rng.uniform(-0.5, 2.0));
    for (int x = 0; x < frame.width; ++x) {
      const float row = float(y) * float(plane.height) / float(frame.height) + 2.0f * std::sin(0.05f * float(x));
      float py = row;
      switch (rng.uniform(0, 14)) {
        case 0: px -= float(rng.uniform(0.2, 2.5)); break;           // a step back
        case 1: px += float(rng.uniform(2.0, 6.0)); break;           // a jump on
        case 2: py = row + float(rng.uniform(-5.0, 5.0)); break;     // rows away
        case 3: px = std::floor(px) + 0.5f; break;                   // a pixel centre
        case 4: px = std::floor(px); py = std::floor(row); break;    // a pixel edge both ways
        case 5: px = -0.5f; break;                                   // the left border
        case 6: px = top_x; break;                                   // the right border
        case 7: py = -0.5f; break;                                   // the top border
        case 8: py = float(plane.height) + float(rng.uniform(0.0, 100.0)); break;  // below the plane
        case 9: py = 9.99e7f; break;                                 // the furthest row allowed
        default: px += float(rng.uniform(0.4, 1.1));
      }
      px = std::min(std::max(px, -0.5f), top_x);
      py = std::max(py, -0.5f);
      positions.at<cv::Vec2f>(y, x) = cv::Vec2f(px, py);
    }
  }
  return positions;
}

void expect_matches_naive(cv::Size frame_size, cv::Size plane, unsigned seed) {
  const cv::Mat positions = wandering_positions(frame_size, plane, seed);
  cv::Mat frame(frame_size, CV_32FC3), factor(plane, CV_32F);
  cv::RNG rng(seed + 1);
  rng.fill(frame, cv::RNG::UNIFORM, 0.0, 100.0);
  rng.fill(factor, cv::RNG::UNIFORM, 0.5, 2.0);
  const FixedSplat splat(positions, plane);
  const cv::Mat ones(plane, CV_32F, cv::Scalar(1.0));
  for (const cv::Mat* f : {&ones, static_cast<const cv::Mat*>(&factor)}) {
    cv::Mat got;
    splat.apply(frame, *f, got);
    ASSERT_EQ(got.size(), plane);
    ASSERT_EQ(got.type(), CV_32FC3);
    cv::Mat reach;
    const cv::Mat want = naive_splat(frame, positions, plane, *f, reach);
    for (int v = 0; v < plane.height; ++v)
      for (int u = 0; u < plane.width; ++u)
        for (int c = 0; c < 3; ++c) {
          const double w = want.at<cv::Vec3d>(v, u)[c], r = reach.at<cv::Vec3d>(v, u)[c];
          // Float sums and shares: a few parts in 1e6 of the values that
          // reach the pixel (a lost share is thousands of times more).
          ASSERT_NEAR(got.at<cv::Vec3f>(v, u)[c], w, 1e-5 * w + 2e-6 * r + 1e-6)
              << "plane " << plane << " pixel " << u << "," << v << " channel " << c;
        }
  }
}

TEST(FixedSplat, WanderingPositionsGetEachPixelsBilinearShares) {
  expect_matches_naive({97, 61}, {80, 45}, 1);     // a block and a half of rows
  expect_matches_naive({64, 20}, {50, 17}, 2);     // shorter than a block
  expect_matches_naive({130, 140}, {121, 96}, 3);  // three whole blocks
}

TEST(FixedSplat, TheSameBytesWhateverTheThreadCount) {
  const cv::Size frame_size(200, 150), plane(160, 111);
  const cv::Mat positions = wandering_positions(frame_size, plane, 7);
  cv::Mat frame(frame_size, CV_32FC3);
  cv::RNG(8).fill(frame, cv::RNG::UNIFORM, 0.0, 1000.0);
  const cv::Mat factor(plane, CV_32F, cv::Scalar(1.0));
  const FixedSplat splat(positions, plane);
  const int threads = cv::getNumThreads();
  cv::Mat one, many;
  cv::setNumThreads(1);
  splat.apply(frame, factor, one);
  cv::setNumThreads(2);
  splat.apply(frame, factor, many);
  cv::setNumThreads(threads);
  EXPECT_EQ(cv::norm(one, many, cv::NORM_INF), 0.0);
}

// The weights' sums (the angle plane's normalisation): channel 0 of a
// frame of ones by a factor of 1, bit for bit, and the shares summed here
// in double.
TEST(FixedSplat, WeightSumsAreASplatOfOnesBitForBit) {
  for (const auto& [frame_size, plane, seed] :
       {std::tuple{cv::Size(97, 61), cv::Size(80, 45), 11u}, std::tuple{cv::Size(130, 140), cv::Size(121, 96), 12u}}) {
    const cv::Mat positions = wandering_positions(frame_size, plane, seed);
    const FixedSplat splat(positions, plane);
    cv::Mat sums, ones_splat;
    splat.weight_sums(sums);
    ASSERT_EQ(sums.size(), plane);
    ASSERT_EQ(sums.type(), CV_32F);
    splat.apply(cv::Mat(frame_size, CV_32FC3, cv::Scalar::all(1.0)), cv::Mat(plane, CV_32F, cv::Scalar(1.0)),
                ones_splat);
    cv::Mat reach;
    const cv::Mat want = naive_splat(cv::Mat(frame_size, CV_32FC3, cv::Scalar::all(1.0)), positions, plane,
                                     cv::Mat(plane, CV_32F, cv::Scalar(1.0)), reach);
    int positive = 0;
    for (int v = 0; v < plane.height; ++v)
      for (int u = 0; u < plane.width; ++u) {
        const float got = sums.at<float>(v, u), ones = ones_splat.at<cv::Vec3f>(v, u)[0];
        ASSERT_EQ(std::memcmp(&got, &ones, sizeof(float)), 0) << "pixel " << u << "," << v;
        const double w = want.at<cv::Vec3d>(v, u)[0];
        ASSERT_NEAR(got, w, 1e-5 * w + 2e-6 * reach.at<cv::Vec3d>(v, u)[0]) << "pixel " << u << "," << v;
        positive += got > 0.0f;
      }
    EXPECT_GT(positive, plane.area() / 10);  // (these positions cover 16-24 % of their planes)
  }
}

TEST(FixedSplat, RefusesPositionsBeyondItsBorders) {
  const cv::Size plane(40, 30);
  for (const cv::Vec2f& bad : {cv::Vec2f(-0.6f, 3.0f), cv::Vec2f(40.5f, 3.0f), cv::Vec2f(3.0f, -0.6f),
                               cv::Vec2f(3.0f, 1e8f), cv::Vec2f(NAN, 3.0f), cv::Vec2f(3.0f, NAN)}) {
    cv::Mat positions(5, 5, CV_32FC2, cv::Scalar(10.0, 10.0));
    positions.at<cv::Vec2f>(2, 3) = bad;
    EXPECT_THROW(FixedSplat(positions, plane), cv::Exception) << bad;
  }
}

}  // namespace
}  // namespace eyestream::pipeline
