// step_cone_row (retina/cone_step_row.hpp) against Jacobs et al. 2015
// eqs. 1, 5, 6, 9 and 10 written out here in double with std::exp and
// std::pow: stimuli from 0 (and non-finite or negative, which count as 0)
// to 1e9 cd/m^2, states across [0, 1] and [0, C_max], a row whose length
// is not a whole number of the function's blocks, and the same results
// for a site wherever it sits in the row; and bit for bit the scalar float
// step with exp_float in place of std::exp.
#include "retina/cone_step_row.hpp"
#include "retina/exp_float.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "retina/tone_curve.hpp"

namespace eyestream::retina {
namespace {

TEST(ConeStepRow, IsTheModelsExactStepWithinFloatRounding) {
  const PhotoreceptorParams p;
  const ToneCurve curve(0.5, ToneCurveParams());
  const double dt = 1.0 / 30.0, c_max = p.calcium_influx_per_s / p.calcium_efflux_per_s;
  ConeStep k;
  for (int c = 0; c < 3; ++c) {
    k.bleach_rate[c] = float(p.bleach_rate[c]);
    k.regen_rate[c] = float(p.regen_rate_per_s[c]);
  }
  k.dt = float(dt);
  k.calcium_decay = float(std::exp(-p.calcium_efflux_per_s * dt));
  k.c_max = float(c_max);
  k.sigma = curve.sigma();
  k.power = &curve.power();
  const int sites = 300;  // two blocks of 128 and a part
  std::mt19937 random(9);
  std::uniform_real_distribution<double> log_l(-6.0, 9.0), unit(0.0, 1.0);
  std::vector<float> s(3 * sites), b(3 * sites), d(3 * sites), rest(3 * sites), r(3 * sites);
  for (size_t j = 0; j < s.size(); ++j) {
    s[j] = float(std::pow(10.0, log_l(random)));
    b[j] = float(unit(random));
    d[j] = float(unit(random) * c_max);
  }
  s[0] = 0.0f, s[4] = -3.0f, s[8] = NAN, s[10] = INFINITY, s[13] = 1e9f;
  const std::vector<float> b0 = b, d0 = d;
  step_cone_row(k, s.data(), rest.data(), r.data(), b.data(), d.data(), sites);
  const double n = ToneCurveParams().exponent, sigma = curve.sigma();
  for (size_t j = 0; j < s.size(); ++j) {
    const int c = int(j % 3);
    const double i = (std::isfinite(s[j]) && s[j] > 0.0f) ? double(s[j]) : 0.0;
    const double b1 = k.bleach_rate[c], b2 = k.regen_rate[c];
    const double want_rest = b1 * i / (b1 * i + b2);                                               // eq. 6
    const double want_r = i > 0.0 ? std::pow(i, n) / (std::pow(i, n) + std::pow(sigma, n)) : 0.0;  // eq. 1
    const double want_b =
        std::clamp((b0[j] - want_rest) * std::exp(-(b1 * i + b2) * dt) + want_rest, 0.0, 1.0);  // eq. 5
    const double want_d = std::clamp((d0[j] - c_max * want_r) * std::exp(-p.calcium_efflux_per_s * dt) + c_max * want_r,
                                     0.0, c_max);  // eqs. 9-10
    EXPECT_NEAR(rest[j], want_rest, 4e-7 * want_rest + 1e-12) << j;
    EXPECT_NEAR(r[j], want_r, 1e-6 * want_r + 1e-12) << j;
    EXPECT_NEAR(b[j], want_b, 1e-6) << j;
    EXPECT_NEAR(d[j], want_d, 1e-6 * c_max) << j;
    // And bit for bit the scalar float step with exp_float for std::exp.
    const float fi = float(i), fb1 = k.bleach_rate[c], fb2 = k.regen_rate[c];
    const float rate = fb1 * fi + fb2, f_rest = fb1 * fi / rate, f_r = curve.response(fi);
    const float stepped = std::clamp((b0[j] - f_rest) * exp_float(-rate * k.dt) + f_rest, 0.0f, 1.0f);
    const float settled = std::clamp((d0[j] - k.c_max * f_r) * k.calcium_decay + k.c_max * f_r, 0.0f, k.c_max);
    ASSERT_EQ(rest[j], f_rest) << j;
    ASSERT_EQ(r[j], f_r) << j;
    ASSERT_EQ(b[j], stepped) << j;
    ASSERT_EQ(d[j], settled) << j;
  }
  // A site's results do not depend on where it sits: the row shifted by
  // one block and a part gives the same bytes.
  const int shift = 131;
  std::vector<float> s2(s.begin() + 3 * shift, s.end()), b2(b0.begin() + 3 * shift, b0.end()),
      d2(d0.begin() + 3 * shift, d0.end()), rest2(s2.size()), r2(s2.size());
  step_cone_row(k, s2.data(), rest2.data(), r2.data(), b2.data(), d2.data(), sites - shift);
  for (size_t j = 0; j < s2.size(); ++j) {
    EXPECT_EQ(rest2[j], rest[j + 3 * shift]) << j;
    EXPECT_EQ(b2[j], b[j + 3 * shift]) << j;
    EXPECT_EQ(d2[j], d[j + 3 * shift]) << j;
    EXPECT_EQ(r2[j], r[j + 3 * shift]) << j;
  }
  // No stimulus responds 0 and reads the power table only in [0, 1],
  // whatever sigma is (here 0, which no tone curve has).
  k.sigma = 0.0f;
  const float dark[3] = {0.0f, -1.0f, NAN}, lit[3] = {1.0f, 2.0f, 3.0f};
  float one_rest[3], one_r[3], one_b[3] = {0.5f, 0.5f, 0.5f}, one_d[3] = {0.5f, 0.5f, 0.5f};
  step_cone_row(k, dark, one_rest, one_r, one_b, one_d, 1);
  for (float v : one_r) EXPECT_EQ(v, 0.0f);
  step_cone_row(k, lit, one_rest, one_r, one_b, one_d, 1);
  for (float v : one_r) EXPECT_EQ(v, 1.0f) << "sigma 0: every stimulus is far above it";
}

}  // namespace
}  // namespace eyestream::retina
