// afterimage_row (retina/afterimage_row.hpp) against the afterimage terms
// written out here one value at a time (Jacobs et al. 2015 eqs. 11-12, as
// RetinaState's loop for any precision computes them in float): the same
// bits for both terms and the largest, with either term off, on rows
// whose length is not a whole number of the function's blocks, with
// excesses of -0 and below 0, and a NaN left out of the largest.
#include "retina/afterimage_row.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "retina/bit_masks.hpp"
#include "retina/photoreceptor.hpp"

namespace eyestream::retina {
namespace {

TEST(AfterimageRow, IsTheTermsOneValueAtATimeBitForBit) {
  const PhotoreceptorParams p;
  const double c_max = p.calcium_influx_per_s / p.calcium_efflux_per_s;
  const PowTable& power = shared_pow_table(p.adaptation_strength);
  std::mt19937 random(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const int sites : {1, 127, 128, 300}) {
    const size_t n = 3 * size_t(sites);
    std::vector<float> b(n), d(n), b_inf(n), r(n), visible(static_cast<size_t>(sites));
    for (size_t j = 0; j < n; ++j) {
      b[j] = float(unit(random));
      b_inf[j] = float(unit(random));
      d[j] = float(unit(random) * unit(random) * c_max);  // down to the dark limit
      r[j] = float(unit(random));
    }
    for (float& v : visible) v = float(unit(random));
    b[0] = b_inf[0] = 0.25f;                   // an excess of 0
    if (n > 4) b[4] = -0.0f, b_inf[4] = 0.0f;  // of -0
    for (const bool gain : {true, false})
      for (const bool bleach : {true, false}) {
        AfterimageTerms k;
        k.gain = gain;
        k.bleach = bleach;
        k.c_max = c_max;
        k.epsilon = float(p.gain_epsilon);
        k.strength = p.bleaching_strength;
        k.power = &power;
        std::vector<float> got_gain(n), got_bleach(n);
        const float largest = afterimage_row(k, b.data(), d.data(), b_inf.data(), r.data(), visible.data(),
                                             got_gain.data(), got_bleach.data(), sites);
        EXPECT_EQ(bits_of(afterimage_row(k, b.data(), d.data(), b_inf.data(), r.data(), visible.data(), nullptr,
                                         nullptr, sites)),
                  bits_of(largest))
            << "without maps";
        float want_largest = 0.0f;
        for (size_t j = 0; j < n; ++j) {
          double g = 1.0, term = 0.0;
          if (gain) g = power.any(float(local_gain<float>(d[j], r[j], float(c_max), float(p.gain_epsilon))));
          if (bleach)
            term = p.bleaching_strength * (1.0 - double(d[j]) / c_max) * std::max(double(b[j] - b_inf[j]), 0.0);
          const double v = visible[j / 3];
          const float want_gain = float(v * (g - 1.0)), want_bleach = float(v * term);
          ASSERT_EQ(bits_of(got_gain[j]), bits_of(want_gain)) << sites << " sites, value " << j;
          ASSERT_EQ(bits_of(got_bleach[j]), bits_of(want_bleach)) << sites << " sites, value " << j;
          want_largest = std::max({want_largest, std::abs(want_gain), std::abs(want_bleach)});
        }
        EXPECT_EQ(bits_of(largest), bits_of(want_largest)) << sites;
      }
  }
  // A NaN term is left out of the largest, as std::max leaves it out.
  AfterimageTerms k;
  k.power = &power;
  k.c_max = c_max;
  const float b[3] = {0.5f, 0.5f, 0.5f}, d[3] = {0.1f, 0.1f, 0.1f}, b_inf[3] = {0.2f, 0.2f, 0.2f},
              r[3] = {0.3f, 0.3f, 0.3f};
  const float nan_visible[1] = {NAN};
  EXPECT_EQ(afterimage_row(k, b, d, b_inf, r, nan_visible, nullptr, nullptr, 1), 0.0f);
}

}  // namespace
}  // namespace eyestream::retina
