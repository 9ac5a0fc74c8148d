// pipeline/geometry/bilinear_splat.hpp on made-up positions: pixels that
// step half a column or one, step back, jump columns and rows, sit on
// pixel centres and edges, or lie beyond the target on every side; over
// targets shorter than a block of rows and not a whole number of blocks,
// and positions that span the whole target's width or only its middle (as
// the frame on the retina's grid, twice the frame each way). Each type
// (three float channels, one, three doubles) against the normalised
// means summed here in double; three float channels also against the
// same sums taken here in float in the order the header gives (the
// image's), bit for bit, on one thread and on all; and the same bytes
// whatever the thread count.
#include "pipeline/geometry/bilinear_splat.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
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

// Positions in the image's pixel units (the target's over a.kx), along
// rows that cross target columns [from, to): mostly steps of 0.7-1.3
// (half a target column or so), the rest steps back, jumps on, rows away,
// exact centres and edges, points above and below the target, and points
// left and right of the span, near, and (when the span is the target's
// whole width) far.
cv::Mat wandering_positions(cv::Size image, cv::Size target, SplatAffine a, unsigned seed, double from, double to) {
  cv::RNG rng(seed);
  cv::Mat positions(image, CV_32FC2);
  const float high = float(target.height / a.ky);
  const float left = float(from / a.kx), right = float(to / a.kx);
  const bool whole = from <= 0.0 && to >= target.width;
  for (int y = 0; y < image.height; ++y) {
    float px = left + float(rng.uniform(-4.0, 4.0));
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
        case 7: qx = left - float(rng.uniform(0.0, 8.0)); break;    // left of the span, near
        case 8: qx = right + float(rng.uniform(0.0, 8.0)); break;   // right of it, near
        case 9: qx = whole ? float(rng.uniform(-1e4, 1e4)) : px; break;  // anywhere, far (the whole width only)
        default: px += float(rng.uniform(0.7, 1.3));
      }
      if (px > right + 4.0f) px = left + float(rng.uniform(-4.0, 4.0));  // past the span: from its left again
      positions.at<cv::Vec2f>(y, x) = cv::Vec2f(qx > -1e8f ? qx : px, py);
    }
  }
  return positions;
}

// Each target pixel's shares summed in double: the normalised means times
// the multiplier, kOutside where nothing lands; `reach` the largest value
// with a share there. The shares are those of the mapped float positions,
// their fractions tx - floor(tx) taken in float as the splat takes them
// (rounded where tx < 0: -0.3375609 gives 0.66243911, not 0.6624391), the
// rest in double.
template <typename T, int C>
cv::Mat naive_means(const cv::Mat& image, const cv::Mat& positions, SplatAffine a, cv::Size size,
                    const cv::Mat& multiplier, cv::Mat& reach) {
  cv::Mat sums(size, CV_64FC4, cv::Scalar::all(0.0));
  reach = cv::Mat(size, CV_64F, cv::Scalar(0.0));
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) {
      const cv::Point2f t = mapped(positions.at<cv::Vec2f>(y, x), a);
      const T* v = image.ptr<T>(y) + size_t(x) * C;
      const float i0 = std::floor(t.x), j0 = std::floor(t.y);
      const double fx = double(t.x - i0), fy = double(t.y - j0);  // (float differences)
      test::for_each_bilinear_share(double(i0) + fx, double(j0) + fy, size, [&](int i, int j, double share) {
        cv::Vec4d& s = sums.at<cv::Vec4d>(j, i);
        for (int c = 0; c < C; ++c) {
          s[c] += double(v[c]) * share;
          reach.at<double>(j, i) = std::max(reach.at<double>(j, i), double(v[c]));
        }
        s[3] += share;
      });
    }
  cv::Mat out(size, CV_64FC(C));
  for (int j = 0; j < size.height; ++j)
    for (int i = 0; i < size.width; ++i) {
      const cv::Vec4d s = sums.at<cv::Vec4d>(j, i);
      const double m = multiplier.empty() ? 1.0 : double(multiplier.at<float>(j, i));
      for (int c = 0; c < C; ++c) out.ptr<double>(j)[size_t(i) * C + c] = s[3] > 0.0 ? s[c] / s[3] * m : kOutside[c];
    }
  return out;
}

// The same sums in float, one pixel after another in the image's order,
// each share (1 - fx or fx) x (1 - fy or fy) and each sum s + v x share,
// each mean (s / weight) x multiplier: as bilinear_splat.cpp makes them.
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
  double from, to;  // the target columns the positions' rows cross (as fractions of its width)
};

std::string case_name(const testing::TestParamInfo<Case>& info) { return "seed" + std::to_string(info.param.seed); }

const Case kCases[] = {
    {{120, 70}, {61, 45}, 1, 0.0, 1.0},     // a block and a half of rows, the whole width
    {{90, 30}, {47, 17}, 2, 0.0, 1.0},      // shorter than a block
    {{200, 190}, {101, 96}, 3, 0.0, 1.0},   // three whole blocks
    {{110, 150}, {113, 75}, 4, 0.3, 0.75},  // the middle of a target twice as wide
};

// The image, positions and multiplier of a case.
struct Inputs {
  cv::Mat positions, image, multiplier;
};

Inputs inputs(const Case& c, int type) {
  Inputs in;
  in.positions =
      wandering_positions(c.image, c.target, kHalf, c.seed, c.from * c.target.width, c.to * c.target.width);
  in.image.create(c.image, type);
  in.multiplier.create(c.target, CV_32F);
  cv::RNG rng(c.seed + 1);
  rng.fill(in.image, cv::RNG::UNIFORM, 0.0, 100.0);
  rng.fill(in.multiplier, cv::RNG::UNIFORM, 0.5, 2.0);
  return in;
}

// Counts the target pixels something reaches and those left outside.
void expect_both_kinds(const cv::Mat& reach, const Case& c) {
  const int landed = cv::countNonZero(reach > 0.0), away = c.target.area() - landed;
  EXPECT_GT(landed, c.target.area() * (c.to - c.from) / 3);
  EXPECT_GT(away, 0);
}

class BilinearSplatCases : public testing::TestWithParam<Case> {};

TEST_P(BilinearSplatCases, ThreeFloatsMatchDoubleSumsAndFloatSumsInImageOrder) {
  const Case& c = GetParam();
  const Inputs in = inputs(c, CV_32FC3);
  cv::Mat reach;
  const cv::Mat want = naive_means<float, 3>(in.image, in.positions, kHalf, c.target, in.multiplier, reach);
  const cv::Mat same = float_means(in.image, in.positions, kHalf, c.target, in.multiplier);
  expect_both_kinds(reach, c);
  const int threads = cv::getNumThreads();
  for (int n : {1, threads}) {  // one thread: one accumulator for every block
    cv::setNumThreads(n);
    const cv::Mat got = bilinear_splat(in.image, in.positions, kHalf, c.target, kOutside, in.multiplier);
    cv::setNumThreads(threads);
    ASSERT_EQ(got.size(), c.target);
    ASSERT_EQ(got.type(), CV_32FC3);
    for (int j = 0; j < c.target.height; ++j)
      for (int i = 0; i < c.target.width; ++i) {
        const cv::Vec3f g = got.at<cv::Vec3f>(j, i);
        ASSERT_EQ(std::memcmp(&g, &same.at<cv::Vec3f>(j, i), sizeof g), 0) << "pixel " << i << "," << j;
        for (int k = 0; k < 3; ++k)
          // A mean of values up to `reach` (times 0.5-2): float sums are off
          // by a few parts in 1e6 of it; a lost or doubled share by far more.
          ASSERT_NEAR(g[k], want.at<cv::Vec3d>(j, i)[k], 1e-5 * reach.at<double>(j, i) + 1e-6)
              << "pixel " << i << "," << j << " channel " << k << ", " << n << " thread(s)";
      }
  }
}

TEST_P(BilinearSplatCases, OneFloatAndThreeDoublesMatchDoubleSums) {
  const Case& c = GetParam();
  for (int type : {CV_32FC1, CV_64FC3}) {
    const Inputs in = inputs(c, type);
    const cv::Mat got = bilinear_splat(in.image, in.positions, kHalf, c.target, kOutside, in.multiplier);
    ASSERT_EQ(got.size(), c.target);
    ASSERT_EQ(got.type(), type);
    cv::Mat reach, want;
    if (type == CV_32FC1) {
      want = naive_means<float, 1>(in.image, in.positions, kHalf, c.target, in.multiplier, reach);
    } else {
      want = naive_means<double, 3>(in.image, in.positions, kHalf, c.target, in.multiplier, reach);
    }
    expect_both_kinds(reach, c);
    // Float sums: a few parts in 1e6 of the values that reach a pixel;
    // double sums of the same float shares: a few parts in 1e15.
    const double tolerance = type == CV_32FC1 ? 1e-5 : 1e-12;
    cv::Mat got64;
    got.convertTo(got64, CV_64F);
    const int channels = got.channels();
    for (int j = 0; j < c.target.height; ++j)
      for (int i = 0; i < c.target.width; ++i)
        for (int k = 0; k < channels; ++k)
          ASSERT_NEAR(got64.ptr<double>(j)[size_t(i) * channels + k], want.ptr<double>(j)[size_t(i) * channels + k],
                      tolerance * reach.at<double>(j, i) + 1e-6)
              << "type " << type << " pixel " << i << "," << j << " channel " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, BilinearSplatCases, testing::ValuesIn(kCases), case_name);

TEST(BilinearSplat, TheSameBytesWhateverTheThreadCount) {
  const Case c{{300, 220}, {151, 111}, 7, 0.0, 1.0};
  const Inputs in = inputs(c, CV_32FC3);
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  const cv::Mat one = bilinear_splat(in.image, in.positions, kHalf, c.target, kOutside, cv::Mat());
  cv::setNumThreads(3);
  const cv::Mat many = bilinear_splat(in.image, in.positions, kHalf, c.target, kOutside, cv::Mat());
  cv::setNumThreads(threads);
  ASSERT_EQ(one.size(), many.size());
  EXPECT_EQ(std::memcmp(one.data, many.data, one.total() * one.elemSize()), 0);
}

}  // namespace
}  // namespace eyestream::pipeline
