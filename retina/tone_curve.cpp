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
  power_ = &shared_pow_table(p.exponent);
}

}  // namespace eyestream::retina
