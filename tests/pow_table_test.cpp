// The power table (retina/pow_table.hpp) against std::pow in double, over
// every octave it covers and below it, for the display gammas.
#include <gtest/gtest.h>

#include <cmath>

#include "retina/pow_table.hpp"

namespace eyestream::retina {
namespace {

TEST(PowTable, MatchesPowWithinItsStatedError) {
  for (double p : {0.455, 1.0 / 2.2, 1.0 / 2.4, 0.5}) {
    const PowTable table(p);
    double worst = 0;
    for (int k = 0; k <= 2000000; ++k) {
      // log-spaced from 1e-14 to 1, and the end points
      const float x = k == 0 ? 0.0f : float(std::pow(10.0, -14.0 + 14.0 * k / 2000000.0));
      const double want = std::pow(double(x), p), got = table(x);
      if (want > 0) worst = std::max(worst, std::abs(got - want) / want);
      else EXPECT_EQ(got, 0.0f);
    }
    EXPECT_LT(worst, 1e-7 * 2) << "p = " << p;  // interpolation plus the float result's own rounding
    EXPECT_EQ(table(1.0f), 1.0f);
    for (float x : {1.5f, 3.0f, 1e3f, 1e9f})  // above 1, by the inverse
      EXPECT_NEAR(table.any(x), std::pow(double(x), p), 4e-7 * std::pow(double(x), p)) << x;
    EXPECT_EQ(table(-0.0f), 0.0f) << "-0, whose sign bit once indexed past the table";
    // A row at a call gives what one value at a call does, below the
    // table's least octave too.
    const float xs[] = {0.0f, -0.0f, 1.0f, 0.5f, 1e-20f, 1e-38f, 3e-13f, 0.123456f, 0.999f};
    float ys[sizeof xs / sizeof *xs];
    table.batch(xs, ys, int(sizeof xs / sizeof *xs));
    for (size_t i = 0; i < sizeof xs / sizeof *xs; ++i) EXPECT_EQ(ys[i], table(xs[i])) << xs[i];
  }
}

}  // namespace
}  // namespace eyestream::retina
