// pipeline/geometry/bilinear_splat.hpp on made-up positions: pixels that
// step half a column or one, step back, jump columns and rows, sit on
// pixel centres and edges, or lie beyond the target on every side; over
// targets shorter than a block of rows and not a whole number of blocks.
// Checked against the normalised means summed here in double, against
// the same sums taken here in float pixel by pixel in the image's order
// (the splat's own contract, so bit for bit), and for the same bytes
// whatever the thread count.
#include "pipeline/geometry/bilinear_splat.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <opencv2/core/utility.hpp>

#include "tests/bilinear_share_oracle.hpp"

namespace eyestream::pipeline {
namespace {

const SplatAffine kHalf{0.5, 0.5, -0.25};  // half a target pixel per image pixel, as the retina's coarse grids
const cv::Scalar kOutside(-1.0, -2.0, -3.0);

// A position's target coordinates as the splat maps them (in float).
cv::Point2f mapped(const cv::Vec2f& p, SplatAffine a) {
  return {p[0] * float(a.kx) + float(a.offset), p[1] * float(a.ky) + float(a.offset)};
}

// Positions in the image's pixel units (the target's over a.kx): mostly
// steps of 0.7-1.3 (half a target column or so), the rest steps back,
// jumps on, rows away, exact centres and edges, and points beyond the
// target's left, right, top and bottom, near and far.
cv::Mat wandering_positions(cv::Size image, cv::Size target, SplatAffine a, unsigned seed) {
  cv::RNG rng(seed);
  cv::Mat positions(image, CV_32FC2);
  const float wide = float(target.width / a.kx), high = float(target.height / a.ky);
  for (int y = 0; y < image.height; ++y) {
    float px = float(rng.uniform(-4.0, 4.0));
    for (int x = 0; x < image.width; ++x) {
      const float row = float(y) * high / float(image.height) + 3.0f * std::sin(0.04f * float(x));
      float py = row, qx = -1e9f;  // qx: a point off the path, for this pixel alone
      switch (rng.uniform(0, 16)) {
        case 0: px -= float(rng.uniform(0.2, 5.0)); break;          // a step back
        case 1: px += float(rng.uniform(3.0, 12.0)); break;         // a jump on
        case 2: py = row + float(rng.uniform(-10.0, 10.0)); break;  // rows away
        case 3: px = std::floor(px) + 0.5f; break;                  // a centre (offset -0.25, k 0.5)
        case 4: px = std::floor(px); py = std::floor(row); break;   // on whole numbers both ways
        case 5: py = -float(rng.uniform(0.0, 30.0)); break;         // above the target
        case 6: py = high + float(rng.uniform(0.0, 30.0)); break;   // below it
        case 7: qx = -float(rng.uniform(0.0, 8.0)); break;          // left of it, near
        case 8: qx = wide + float(rng.uniform(0.0, 8.0)); break;    // right of it, near
        case 9: qx = float(rng.uniform(-1e4, 1e4)); break;          // anywhere, far
        default: px += float(rng.uniform(0.7, 1.3));
      }
      if (px > wide + 4.0f) px = float(rng.uniform(-4.0, 4.0));  // off the right: from the left again
      positions.at<cv::Vec2f>(y, x) = cv::Vec2f(qx > -1e8f ? qx : px, py);
    }
  }
  return positions;
}

// Each target pixel's shares summed in double (the shares of the mapped
// float positions): the normalised means times the multiplier, kOutside
// where nothing lands; `reach` the largest value with a share there.
cv::Mat naive_means(const cv::Mat& image, const cv::Mat& positions, SplatAffine a, cv::Size size,
                    const cv::Mat& multiplier, cv::Mat& reach) {
  cv::Mat sums(size, CV_64FC4, cv::Scalar::all(0.0));
  reach = cv::Mat(size, CV_64F, cv::Scalar(0.0));
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) {
      const cv::Point2f t = mapped(positions.at<cv::Vec2f>(y, x), a);
      const cv::Vec3f v = image.at<cv::Vec3f>(y, x);
      test::for_each_bilinear_share(t.x, t.y, size, [&](int i, int j, double share) {
        sums.at<cv::Vec4d>(j, i) += cv::Vec4d(v[0], v[1], v[2], 1.0) * share;
        reach.at<double>(j, i) = std::max({reach.at<double>(j, i), double(v[0]), double(v[1]), double(v[2])});
      });
    }
  cv::Mat out(size, CV_64FC3);
  for (int j = 0; j < size.height; ++j)
    for (int i = 0; i < size.width; ++i) {
      const cv::Vec4d s = sums.at<cv::Vec4d>(j, i);
      for (int c = 0; c < 3; ++c)
        out.at<cv::Vec3d>(j, i)[c] = s[3] > 0.0 ? s[c] / s[3] * double(multiplier.at<float>(j, i)) : kOutside[c];
    }
  return out;
}

// The same sums in float, one pixel after another in the image's order,
// each share (1 - fx or fx) x (1 - fy or fy) and each sum s + v x share:
// the order and arithmetic the splat promises (bilinear_splat.hpp).
cv::Mat float_means(const cv::Mat& image, const cv::Mat& positions, SplatAffine a, cv::Size size,
                    const cv::Mat& multiplier) {
  cv::Mat sums(size, CV_32FC4, cv::Scalar::all(0.0));
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) {
      const cv::Point2f t = mapped(positions.at<cv::Vec2f>(y, x), a);
      const int i0 = int(std::floor(t.x)), j0 = int(std::floor(t.y));
      const float fx = t.x - float(i0), fy = t.y - float(j0);
      const cv::Vec3f v = image.at<cv::Vec3f>(y, x);
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) {
          const int i = i0 + di, j = j0 + dj;
          if (i < 0 || j < 0 || i >= size.width || j >= size.height) continue;
          const float share = (di ? fx : 1.0f - fx) * (dj ? fy : 1.0f - fy);
          cv::Vec4f& s = sums.at<cv::Vec4f>(j, i);
          for (int c = 0; c < 3; ++c) s[c] = s[c] + v[c] * share;
          s[3] = s[3] + share;
        }
    }
  cv::Mat out(size, CV_32FC3);
  for (int j = 0; j < size.height; ++j)
    for (int i = 0; i < size.width; ++i) {
      const cv::Vec4f s = sums.at<cv::Vec4f>(j, i);
      for (int c = 0; c < 3; ++c) {
        const float q = s[c] / s[3];
        out.at<cv::Vec3f>(j, i)[c] = s[3] > 0.0f ? q * multiplier.at<float>(j, i) : float(kOutside[c]);
      }
    }
  return out;
}

struct Case {
  cv::Size image, target;
  unsigned seed;
};

class BilinearSplatCases : public testing::TestWithParam<Case> {};

TEST_P(BilinearSplatCases, MeansMatchDoubleSumsAndFloatSumsInImageOrder) {
  const Case& c = GetParam();
  const cv::Mat positions = wandering_positions(c.image, c.target, kHalf, c.seed);
  cv::Mat image(c.image, CV_32FC3), multiplier(c.target, CV_32F);
  cv::RNG rng(c.seed + 1);
  rng.fill(image, cv::RNG::UNIFORM, 0.0, 100.0);
  rng.fill(multiplier, cv::RNG::UNIFORM, 0.5, 2.0);
  const cv::Mat got = bilinear_splat(image, positions, kHalf, c.target, kOutside, multiplier);
  ASSERT_EQ(got.size(), c.target);
  ASSERT_EQ(got.type(), CV_32FC3);
  cv::Mat reach;
  const cv::Mat want = naive_means(image, positions, kHalf, c.target, multiplier, reach);
  const cv::Mat same = float_means(image, positions, kHalf, c.target, multiplier);
  int landed = 0, away = 0;
  for (int j = 0; j < c.target.height; ++j)
    for (int i = 0; i < c.target.width; ++i) {
      const cv::Vec3f g = got.at<cv::Vec3f>(j, i);
      ASSERT_EQ(std::memcmp(&g, &same.at<cv::Vec3f>(j, i), sizeof g), 0) << "pixel " << i << "," << j;
      for (int k = 0; k < 3; ++k)
        // A mean of values up to `reach` (times 0.5-2): float sums are off
        // by a few parts in 1e6 of it; a lost or doubled share by far more.
        ASSERT_NEAR(g[k], want.at<cv::Vec3d>(j, i)[k], 1e-5 * reach.at<double>(j, i) + 1e-6)
            << "pixel " << i << "," << j << " channel " << k;
      (reach.at<double>(j, i) > 0.0 ? landed : away) += 1;
    }
  // Both kinds present: pixels that something reaches and pixels left outside.
  EXPECT_GT(landed, c.target.area() / 3);
  EXPECT_GT(away, 0);
}

INSTANTIATE_TEST_SUITE_P(Targets, BilinearSplatCases,
                         testing::Values(Case{{120, 70}, {61, 45}, 1},     // a block and a half of rows
                                         Case{{90, 30}, {47, 17}, 2},      // shorter than a block
                                         Case{{200, 190}, {101, 96}, 3}),  // three whole blocks
                         [](const testing::TestParamInfo<Case>& info) {
                           return "seed" + std::to_string(info.param.seed);
                         });

TEST(BilinearSplat, TheSameBytesWhateverTheThreadCount) {
  const cv::Size image_size(300, 220), target(151, 111);
  const cv::Mat positions = wandering_positions(image_size, target, kHalf, 7);
  cv::Mat image(image_size, CV_32FC3);
  cv::RNG(8).fill(image, cv::RNG::UNIFORM, 0.0, 1000.0);
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  const cv::Mat one = bilinear_splat(image, positions, kHalf, target, kOutside, cv::Mat());
  cv::setNumThreads(3);
  const cv::Mat many = bilinear_splat(image, positions, kHalf, target, kOutside, cv::Mat());
  cv::setNumThreads(threads);
  ASSERT_EQ(one.size(), many.size());
  EXPECT_EQ(std::memcmp(one.data, many.data, one.total() * one.elemSize()), 0);
}

}  // namespace
}  // namespace eyestream::pipeline
