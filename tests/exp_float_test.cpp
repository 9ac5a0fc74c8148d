// exp_float (retina/exp_float.hpp) against std::exp in double: its stated
// relative error over [-87.3, 88], every float in [-1, 0] near 0 (the
// decays' usual range), and 0 below -87.3.
#include "retina/exp_float.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace eyestream::retina {
namespace {

TEST(ExpFloat, MatchesExpWithinItsStatedError) {
  double worst = 0.0;
  const auto check = [&](float x) {
    const double exact = std::exp(double(x)), got = exp_float(x);
    const double relative = std::abs(got - exact) / exact;
    worst = std::max(worst, relative);
    EXPECT_LT(relative, 1.5e-7) << x;
  };
  std::mt19937 random(3);
  std::uniform_real_distribution<float> wide(-87.3f, 88.0f);
  for (int i = 0; i < 1000000; ++i) check(wide(random));
  for (float x = 0.0f; x > -1.0f; x = std::nextafter(x, -2.0f) - 1e-7f) check(x);  // dense near 0
  for (float x : {0.0f, -0.0f, 1.0f, -1.0f, std::log(2.0f), -87.3f, 88.0f, -1e-30f, 1e-30f}) check(x);
  EXPECT_EQ(exp_float(0.0f), 1.0f);
  EXPECT_EQ(exp_float(-87.4f), 0.0f);
  EXPECT_EQ(exp_float(-1e30f), 0.0f);
  EXPECT_EQ(exp_float(-INFINITY), 0.0f);
  RecordProperty("worst_relative_error", std::to_string(worst));
}

}  // namespace
}  // namespace eyestream::retina
