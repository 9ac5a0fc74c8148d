#include "retina/tone_curve.hpp"

#include <cmath>

namespace eyestream::retina {

double plateau(double log_l, const ToneCurveParams& p) {
  return p.plateau_low +
         (p.plateau_high - p.plateau_low) / (1.0 + std::exp(-(log_l - p.plateau_mid_log) / p.plateau_width_log));
}

ToneCurve::ToneCurve(double adaptation_log, const ToneCurveParams& p) {
  const double m = plateau(adaptation_log, p);
  // Jacobs et al. 2015 eq. 2: sigma = (Ib^n / M - Ib^n)^(1/n) = Ib (1/M - 1)^(1/n)
  const double log_sigma = adaptation_log + std::log10(1.0 / m - 1.0) / p.exponent;
  sigma_ = float(std::pow(10.0, log_sigma));
  exponent_ = float(p.exponent);
}

float ToneCurve::response(float luminance) const {
  if (!(luminance > 0.0f)) return 0.0f;
  // Jacobs et al. 2015 eq. 1 written as 1 / (1 + (sigma/I)^n): no overflow of I^n.
  return 1.0f / (1.0f + std::pow(sigma_ / luminance, exponent_));
}

}  // namespace eyestream::retina
