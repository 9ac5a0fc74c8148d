#include "retina/display_encoding.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "retina/hash_random.hpp"
#include "retina/pow_table.hpp"
#include "tests/test_support.hpp"

namespace eyestream::retina {
namespace {

TEST(DisplayEncoding, AppliesGammaAndClips) {
  cv::Mat linear = test::constant_frame(3, 1, {0.25f, 2.0f, -1.0f});
  cv::Mat code;
  encode_display(linear, 8, 0, EncodingParams{0.5, false, 0}, code);
  const cv::Vec3b p = code.at<cv::Vec3b>(0, 0);
  EXPECT_EQ(p[0], 128);  // 0.25^0.5 * 255 = 127.5, rounded to nearest even/up
  EXPECT_EQ(p[1], 255);
  EXPECT_EQ(p[2], 0);
}

// Mean encoded value of `frames` encodings of `linear`, per pixel and channel.
cv::Mat mean_code(const cv::Mat& linear, int frames, bool dither) {
  cv::Mat sum = cv::Mat::zeros(linear.size(), CV_64FC3), code, code64;
  for (int f = 0; f < frames; ++f) {
    encode_display(linear, 8, f, EncodingParams{0.455, dither, 7}, code);
    code.convertTo(code64, CV_64FC3);
    sum += code64;
  }
  return sum / (255.0 * frames);
}

TEST(DisplayEncoding, DitheredMeanOfManyFramesMatchesTheUnquantisedValue) {
  // A constant dark ramp, encoded values 0.02 .. 0.083 (docs/model.md). Each
  // dithered code is exact +- one step with mean error 0, so the mean of N
  // frames has a standard deviation of at most 0.5/255/sqrt(N): the RMS
  // error over the ramp must stay within 1/255/sqrt(N) and within that
  // standard deviation, and no value may stray past four of them. Plain
  // rounding instead keeps a bias of up to half a code whatever N.
  const int width = 64, frames = 400;
  cv::Mat linear(1, width, CV_32FC3);
  std::vector<double> exact(width);
  for (int x = 0; x < width; ++x) {
    exact[size_t(x)] = 0.02 + 0.001 * x;
    const float v = float(std::pow(exact[size_t(x)], 1.0 / 0.455));
    linear.at<cv::Vec3f>(0, x) = cv::Vec3f(v, v, v);
  }
  const double sigma = 0.5 / 255.0 / std::sqrt(double(frames));
  auto errors = [&](const cv::Mat& mean, double& rms, double& worst) {
    double sq = 0;
    worst = 0;
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double e = mean.at<cv::Vec3d>(0, x)[c] - exact[size_t(x)];
        sq += e * e;
        worst = std::max(worst, std::abs(e));
      }
    rms = std::sqrt(sq / (3 * width));
  };
  double rms, worst;
  errors(mean_code(linear, frames, true), rms, worst);
  EXPECT_LT(rms, 1.0 / 255.0 / std::sqrt(double(frames)));
  EXPECT_LT(rms, sigma);
  EXPECT_LT(worst, 4 * sigma);
  errors(mean_code(linear, frames, false), rms, worst);
  EXPECT_GT(worst, 10 * sigma);
}

TEST(DisplayEncoding, DitherIsAFunctionOfSeedFrameAndPositionOnly) {
  cv::Mat linear(37, 53, CV_32FC3);
  cv::randu(linear, 0.0, 1.0);
  cv::Mat a, b, c, d;
  encode_display(linear, 8, 3, EncodingParams{0.455, true, 1}, a);
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  encode_display(linear, 8, 3, EncodingParams{0.455, true, 1}, b);
  cv::setNumThreads(threads);
  encode_display(linear, 8, 4, EncodingParams{0.455, true, 1}, c);
  encode_display(linear, 8, 3, EncodingParams{0.455, true, 2}, d);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, c, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, d, cv::NORM_INF), 0.0);
}

// The encoding's vectorised rows (compiled for AVX-512 and AVX2 where the
// machine has them) give exactly the codes of the definition written out
// here value by value: clamp (non-finite and -0 to 0), the gamma table
// (std::pow below its least octave), the pixel's hash for the dither; on
// random values and on the awkward ones, 8 and 16 bits, with and without
// dither. Rows of 600 pixels: two whole steps of 256 and a part of one.
// encode_display_row gives each row's codes alike.
TEST(DisplayEncoding, TheVectorisedRowsGiveTheDefinitionsCodes) {
  cv::Mat linear(23, 600, CV_32FC3);
  cv::RNG rng(11);
  rng.fill(linear, cv::RNG::UNIFORM, -0.1, 1.1);
  const float awkward[] = {-0.0f, 0.0f, 1.0f, 1e-20f, 3e-13f, 1e-38f, 2.0f, -5.0f, NAN, INFINITY, -INFINITY, 0.5f};
  for (size_t i = 0; i < sizeof awkward / sizeof *awkward; ++i) linear.at<float>(int(i % 5), int(i)) = awkward[i];
  const PowTable& gamma = shared_pow_table(0.455);
  for (const int bits : {8, 16})
    for (const bool dither : {true, false}) {
      const EncodingParams p{0.455, dither, 5};
      cv::Mat code;
      encode_display(linear, bits, 9, p, code);
      const float max_code = bits == 8 ? 255.0f : 65535.0f;
      int differ = 0;
      for (int y = 0; y < linear.rows; ++y) {
        const std::uint64_t row = hash_row(5, std::uint64_t(RandomStream::kDither), 9, std::uint64_t(y));
        for (int x = 0; x < linear.cols; ++x)
          for (int c = 0; c < 3; ++c) {
            float j = linear.at<cv::Vec3f>(y, x)[c];
            j = std::isfinite(j) && j > 0.0f ? std::min(j, 1.0f) : 0.0f;
            const float v = gamma(j) * max_code;
            const float lo = std::floor(v);
            const float q = dither ? lo + ((v - lo) > hash_uniform3(hash_pixel(row, std::uint64_t(x)), c) ? 1.0f : 0.0f)
                                   : std::nearbyint(v);
            const double want = std::min(q, max_code);
            const double got = bits == 8 ? code.at<cv::Vec3b>(y, x)[c] : code.at<cv::Vec3w>(y, x)[c];
            differ += want != got;
          }
      }
      EXPECT_EQ(differ, 0) << bits << " bits, dither " << dither;
      cv::Mat by_rows(code.size(), code.type());
      for (int y = 0; y < linear.rows; ++y)
        encode_display_row(linear.ptr<float>(y), linear.cols, y, 9, p, bits, by_rows.ptr(y));
      EXPECT_EQ(cv::norm(by_rows, code, cv::NORM_INF), 0.0) << bits << " bits, dither " << dither;
    }
}

TEST(DisplayEncoding, SixteenBitsUseTheFullRange) {
  cv::Mat code;
  encode_display(test::constant_frame(1, 1, {1.0f, 0.0f, 1.0f}), 16, 0, EncodingParams{}, code);
  EXPECT_EQ(code.type(), CV_16UC3);
  EXPECT_EQ(code.at<cv::Vec3w>(0, 0)[0], 65535);
  EXPECT_EQ(code.at<cv::Vec3w>(0, 0)[1], 0);
}

}  // namespace
}  // namespace eyestream::retina
