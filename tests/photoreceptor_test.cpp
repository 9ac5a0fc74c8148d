#include "retina/photoreceptor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "retina/tone_curve.hpp"

namespace eyestream::retina {
namespace {

const PhotoreceptorParams kP;

// Classic RK4 on dB/dt = b1 (1 - B) I - b2 B (Jacobs et al. 2015 eq. 4).
double integrate_bleaching(double b, double i, double dt, double b1, double b2, int steps) {
  auto f = [&](double x) { return b1 * (1 - x) * i - b2 * x; };
  const double h = dt / steps;
  for (int k = 0; k < steps; ++k) {
    const double k1 = f(b), k2 = f(b + h / 2 * k1), k3 = f(b + h / 2 * k2), k4 = f(b + h * k3);
    b += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return b;
}

// RK4 on dC/dt = c1 (1 - R) - c2 C (Jacobs et al. 2015 eq. 8 with S = 1 - R).
double integrate_calcium(double c, double r, double dt, double c1, double c2, int steps) {
  auto f = [&](double x) { return c1 * (1 - r) - c2 * x; };
  const double h = dt / steps;
  for (int k = 0; k < steps; ++k) {
    const double k1 = f(c), k2 = f(c + h / 2 * k1), k3 = f(c + h / 2 * k2), k4 = f(c + h * k3);
    c += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return c;
}

TEST(Photoreceptor, ExactBleachingStepMatchesFineIntegration) {
  for (double dt : {1e-3, 1e-2, 0.1, 1.0, 10.0})
    for (double i : {0.0, 10.0, 1e3, 1e5, 1e7})
      for (int c = 0; c < 3; ++c)
        for (double b0 : {0.0, 0.3, 1.0}) {
          const double b1 = kP.bleach_rate[c], b2 = kP.regen_rate_per_s[c];
          const int steps = int(std::ceil(dt * (b1 * i + b2) * 200)) + 10;  // h*rate <= 1/200
          const double exact = bleach_step(b0, i, dt, b1, b2);
          EXPECT_NEAR(exact, integrate_bleaching(b0, i, dt, b1, b2, steps), 1e-9)
              << "dt=" << dt << " I=" << i << " cone=" << c << " B0=" << b0;
        }
}

TEST(Photoreceptor, ExactCalciumStepMatchesFineIntegration) {
  const double c_max = kP.calcium_influx_per_s / kP.calcium_efflux_per_s;
  for (double dt : {1e-3, 1e-2, 0.1, 1.0, 10.0})
    for (double r : {0.0, 0.2, 0.9})
      for (double c0 : {0.0, 0.5, 1.0}) {
        const double d = deficit_step(c_max - c0, r, dt, c_max, kP.calcium_efflux_per_s);
        const double numeric = integrate_calcium(c0, r, dt, kP.calcium_influx_per_s, kP.calcium_efflux_per_s, 20000);
        EXPECT_NEAR(c_max - d, numeric, 1e-9) << "dt=" << dt << " R=" << r << " C0=" << c0;
      }
}

TEST(Photoreceptor, GainIsOneAtRestBelowOneWhenCalciumLagsAndFiniteInTheDark) {
  const double c_max = 1.0, e = kP.gain_epsilon;
  EXPECT_DOUBLE_EQ(local_gain(0.4, 0.4, c_max, e), 1.0);
  // C < C_inf (D > D_inf): alpha < 1 (Jacobs et al. 2015 after eq. 11).
  EXPECT_LT(local_gain(0.8, 0.2, c_max, e), 1.0);
  EXPECT_GT(local_gain(0.1, 0.6, c_max, e), 1.0);
  // The dark limit R -> 0, C -> C_max (D -> 0): 0/0 in eq. 11, here finite.
  EXPECT_DOUBLE_EQ(local_gain(0.0, 0.0, c_max, e), 1.0);
  EXPECT_LE(local_gain(0.0, 1.0, c_max, e), (c_max + e * c_max) / (e * c_max));
  // Away from the dark limit, close to eq. 11.
  EXPECT_NEAR(local_gain(0.5, 0.25, c_max, e), 0.5, 0.01);
}

TEST(Photoreceptor, StateStaysBoundedOverAMillionRandomSteps) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> log_i(-6.0, 9.0), log_dt(-7.0, 2.8), unit(0.0, 1.0);
  const ToneCurve curve(1.0, ToneCurveParams{});
  const float c_max = 1.0f;
  float b[3] = {0, 0, 0}, d[3] = {0, 0, 0};
  for (int k = 0; k < 1000000; ++k) {
    const float i = float(std::pow(10.0, log_i(rng)));
    const float dt = unit(rng) < 0.01 ? 0.0f : float(std::pow(10.0, log_dt(rng)));  // up to ~10 min, and 0
    const float r = curve.response(i);
    for (int c = 0; c < 3; ++c) {
      b[c] = bleach_step(b[c], i, dt, float(kP.bleach_rate[c]), float(kP.regen_rate_per_s[c]));
      d[c] = deficit_step(d[c], r, dt, c_max, float(kP.calcium_efflux_per_s));
      ASSERT_TRUE(b[c] >= 0.0f && b[c] <= 1.0f) << "step " << k << " B=" << b[c];
      ASSERT_TRUE(d[c] >= 0.0f && d[c] <= c_max) << "step " << k << " D=" << d[c];
      ASSERT_TRUE(std::isfinite(local_gain(d[c], r, c_max, float(kP.gain_epsilon))));
    }
  }
}

}  // namespace
}  // namespace eyestream::retina
