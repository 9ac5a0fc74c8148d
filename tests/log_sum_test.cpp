// log2_sum (retina/log_sum.hpp) against std::log2 in double: each value
// over the whole float range (subnormals, the boundaries of the mantissa's
// split at sqrt(2), the largest float), and a long row's sum.
#include "retina/log_sum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace eyestream::retina {
namespace {

// The result's own rounding (e plus a fraction: a few units in the last
// place of a value up to 150) and the series' truncation (1e-15).
double allowed(double exact) { return 4.0 * std::abs(exact) * std::numeric_limits<double>::epsilon() + 1e-15; }

TEST(LogSum, EachValuesLog2IsTheLibrarysWithinItsStatedError) {
  std::vector<float> values = {std::numeric_limits<float>::denorm_min(),
                               std::numeric_limits<float>::min(),
                               std::numeric_limits<float>::max(),
                               1.0f,
                               2.0f,
                               0.5f,
                               1e-6f,
                               10.0f,
                               1e9f,
                               std::nextafter(std::sqrt(2.0f), 0.0f),
                               std::sqrt(2.0f),
                               std::nextafter(std::sqrt(2.0f), 2.0f),
                               std::nextafter(std::sqrt(0.5f), 0.0f),
                               std::sqrt(0.5f),
                               std::nextafter(1.0f, 0.0f),
                               std::nextafter(1.0f, 2.0f)};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> exponent(-149.0, 128.0);
  for (int i = 0; i < 200000; ++i) {
    const float v = float(std::exp2(exponent(random)));
    if (v > 0.0f && std::isfinite(v)) values.push_back(v);
  }
  double worst = 0.0;
  for (float v : values) {
    const double exact = std::log2(double(v)), got = log2_sum(&v, 1);
    EXPECT_LE(std::abs(got - exact), allowed(exact)) << v;
    worst = std::max(worst, std::abs(got - exact) / allowed(exact));
  }
  RecordProperty("worst_share_of_bound", std::to_string(worst));
}

TEST(LogSum, ARowsSumIsTheSumOfItsLogsAtAnyLength) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> log_luminance(-6.0, 9.0);
  std::vector<float> row(2000);
  for (float& v : row) v = float(std::pow(10.0, log_luminance(random)));
  // Lengths around the partial sums' and the blocks' sizes.
  for (int n : {0, 1, 7, 8, 9, 255, 256, 257, 1000, 2000}) {
    long double exact = 0.0L;
    for (int i = 0; i < n; ++i) exact += std::log2(static_cast<long double>(row[size_t(i)]));
    const double got = log2_sum(row.data(), n);
    EXPECT_NEAR(got, double(exact), 1e-12 * std::max(1.0, std::abs(double(exact)))) << n;
  }
}

}  // namespace
}  // namespace eyestream::retina
