// glare::is_uniform_field against its definition written out here (every
// channel's range within the tolerance, the grey surround within every
// widened range), on fields that differ from uniform in one pixel at
// different places, or in the surround alone, or in nothing; a NaN pixel
// or surround is never uniform.
#include "glare/uniform_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace eyestream::glare {
namespace {

bool by_definition(const cv::Mat& rgb, double surround, double tolerance) {
  const double spread = 1.0 + tolerance;
  for (int c = 0; c < 3; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (int y = 0; y < rgb.rows; ++y)
      for (int x = 0; x < rgb.cols; ++x) {
        const double v = rgb.at<cv::Vec3f>(y, x)[c];
        if (!(v >= 0.0)) return false;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    if (hi > spread * lo || !(surround >= lo / spread && surround <= hi * spread)) return false;
  }
  return true;
}

TEST(UniformField, AgreesWithItsDefinitionWhereverTheFieldDiffers) {
  const double tolerance = 1e-3;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> factor(1.0 - 3e-3, 1.0 + 3e-3);
  int uniform = 0, cases = 0;
  for (const cv::Size size : {cv::Size(31, 17), cv::Size(1, 1), cv::Size(8, 1)}) {
    for (int trial = 0; trial < 400; ++trial) {
      const float base = float(std::pow(10.0, trial % 7 - 3));
      cv::Mat field(size, CV_32FC3, cv::Scalar::all(base));
      // One pixel off by up to 0.3 % somewhere (the first, the middle row,
      // elsewhere), or none; the surround off by up to 0.3 % (or 3x).
      const int where = trial % 4;
      const cv::Point p = where == 0 ? cv::Point(0, 0)
                          : where == 1
                              ? cv::Point(size.width / 2, size.height / 2)
                              : cv::Point(int(random() % unsigned(size.width)), int(random() % unsigned(size.height)));
      if (where != 3) field.at<cv::Vec3f>(p)[int(random() % 3u)] = float(base * factor(random));
      const double surround = trial % 11 == 0 ? base * 3.0 : base * factor(random);
      const bool want = by_definition(field, surround, tolerance);
      EXPECT_EQ(is_uniform_field(field, surround, tolerance), want) << size << " trial " << trial;
      uniform += want;
      ++cases;
    }
  }
  // Both answers were asked for often.
  EXPECT_GT(uniform, cases / 10);
  EXPECT_LT(uniform, cases * 4 / 5);
  cv::Mat with_nan(5, 5, CV_32FC3, cv::Scalar::all(1.0));
  with_nan.at<cv::Vec3f>(4, 4)[1] = NAN;
  EXPECT_FALSE(is_uniform_field(with_nan, 1.0, tolerance));
  EXPECT_TRUE(is_uniform_field(cv::Mat(0, 0, CV_32FC3), 0.0, tolerance));
  EXPECT_FALSE(is_uniform_field(cv::Mat(5, 5, CV_32FC3, cv::Scalar::all(1.0)), NAN, tolerance)) << "a NaN surround";
}

}  // namespace
}  // namespace eyestream::glare
