// The Naka-Rushton tone curve parameterised by the adaptation level
// (Jacobs et al. 2015 eqs. 1-2).
#pragma once

#include "retina/pow_table.hpp"

namespace eyestream::retina {

// The plateau M(L) is the response a steady background L settles to. Seed
// 001 gives only its shape ("similar to eq. 1", after Dowling); eyestream
// uses a logistic in log10 L rising from plateau_low (darkness) to
// plateau_high (daylight), centred at plateau_mid_log with slope width
// plateau_width_log:
//   M(L) = low + (high - low) / (1 + exp(-(log10 L - mid) / width))
// With the defaults an adapted background shows at J = 0.034 under starlight
// (1e-3 cd/m^2), 0.097 on a lit night road (1 cd/m^2), 0.26 in an office
// (100 cd/m^2) and 0.37 in daylight (1e4 cd/m^2): display codes 0.22, 0.35,
// 0.54 and 0.64 after gamma 0.455. Night looks dark, day mid-grey.
struct ToneCurveParams {
  double exponent = 0.7;           // n (Jacobs et al. 2015 App. A)
  double plateau_low = 0.03;       // M in total darkness
  double plateau_high = 0.40;      // M in bright daylight
  double plateau_mid_log = 1.5;    // log10 cd/m^2 where M is halfway
  double plateau_width_log = 1.0;  // log10 units
};

double plateau(double log_luminance, const ToneCurveParams& p);

// Naka-Rushton curve for one adaptation level. sigma follows from R(Ib) =
// M(Ib): sigma = Ib (1/M - 1)^(1/n) (Jacobs et al. 2015 eq. 2, solved in log form so
// 1e-6 .. 1e9 cd/m^2 stay finite). Immutable and thread-safe.
class ToneCurve {
 public:
  ToneCurve(double adaptation_log, const ToneCurveParams& p);
  // R(I) = I^n / (I^n + sigma^n) in [0, 1); 0 for I <= 0 or NaN; 1 for +inf
  // (Jacobs et al. 2015 eq. 1). The power comes from a table (relative
  // error under 2e-7, pow_table.hpp).
  float response(float luminance) const {
    if (!(luminance > 0.0f)) return 0.0f;
    // As 1 / (1 + (sigma/I)^n), no overflow of I^n; the table takes the
    // ratio or its inverse, whichever is at most 1.
    const float ratio = sigma_ / luminance;
    if (ratio <= 1.0f) return 1.0f / (1.0f + (*power_)(ratio));
    const float q = (*power_)(1.0f / ratio);
    return q / (q + 1.0f);
  }
  // Its half-response luminance and its power table, for loops that take
  // response() apart to run a row at a time (tone_map.cpp).
  float sigma() const { return sigma_; }
  const PowTable& power() const { return *power_; }

 private:
  float sigma_;
  const PowTable* power_;  // x^n for x in [0, 1]
};

}  // namespace eyestream::retina
