// One cone's photopigment bleaching and calcium state, stepped exactly
// (Jacobs et al. 2015 eqs. 4-6 and 8-12). Header-only so the
// per-site loops inline it; templated on float (default) or double
// (reference precision).
#pragma once

#include <algorithm>
#include <cmath>

namespace eyestream::retina {

// Per-cone rates for L, M, S (Jacobs et al. 2015 App. A).
struct PhotoreceptorParams {
  double bleach_rate[3] = {1.2e-3, 1.4e-4, 5.5e-7};  // b1, per (cd/m^2 s)
  double regen_rate_per_s[3] = {0.69, 1.4, 5.5};     // b2
  double calcium_influx_per_s = 1.0;                 // c1
  double calcium_efflux_per_s = 1.0;                 // c2
  double bleaching_strength = 0.03;                  // j1
  double adaptation_strength = 0.15;                 // j2, an exponent (docs/model.md)
  // Regularises the gain alpha in the dark limit, as a fraction of C_max
  // (see local_gain).
  double gain_epsilon = 0.01;
};

// Equilibrium bleached fraction for stimulus I >= 0 (Jacobs et al. 2015 eq. 6).
template <typename T>
inline T bleach_equilibrium(T intensity, T b1, T b2) {
  return b1 * intensity / (b1 * intensity + b2);
}

// B after dt at constant stimulus I: (B - B_inf) e^{-(b1 I + b2) dt} + B_inf
// (Jacobs et al. 2015 eq. 5). Exact for any dt >= 0; the result stays in [0, 1] when
// B does, because it is a convex combination of B and B_inf.
template <typename T>
inline T bleach_step(T bleached, T intensity, T dt, T b1, T b2) {
  const T b_inf = bleach_equilibrium(intensity, b1, b2);
  return (bleached - b_inf) * std::exp(-(b1 * intensity + b2) * dt) + b_inf;
}

// Calcium is kept as its deficit D = C_max - C in [0, C_max], which turns
// Jacobs et al. 2015 eq. 8 with S = 1 - R into dD/dt = c1 R - c2 D: equilibrium
// D_inf = C_max R (eq. 10), exact step D' = (D - D_inf) e^{-c2 dt} + D_inf
// (eq. 9). Kept this way, the gain below needs no difference of two nearly
// equal numbers in the dark.
template <typename T>
inline T deficit_step(T deficit, T response, T dt, T c_max, T c2) {
  const T d_inf = c_max * response;
  return (deficit - d_inf) * std::exp(-c2 * dt) + d_inf;
}

// alpha = (C_max - C_inf) / (C_max - C) = D_inf / D (Jacobs et al. 2015 eq. 11). In
// the dark both tend to 0 (0/0); eyestream uses (D_inf + e) / (D + e) with
// e = gain_epsilon * C_max: exactly 1 at equilibrium, finite and bounded by
// (C_max + e) / e everywhere, and within a fraction e/D of eq. 11 when D >> e.
template <typename T>
inline T local_gain(T deficit, T response, T c_max, T epsilon) {
  const T e = epsilon * c_max;
  return (c_max * response + e) / (deficit + e);
}

}  // namespace eyestream::retina
