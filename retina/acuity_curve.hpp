// The finest grating a viewer resolves at a given luminance: Shlaer's (1937)
// acuity data as fitted by Ward Larson, Rushmeier and Piatko (1997, "A
// visibility matching tone reproduction operator for high dynamic range
// scenes", IEEE TVCG 3(4)), the curve Ferwerda et al. (1996) also model:
//   f(L) = 17.25 atan(1.4 log10 L + 0.35) + 25.72  c/deg,
// about 3.0 c/deg at 0.001 cd/m^2, 5.3 at 0.01, 11.7 at 0.1, 31.5 at 1 and
// 46 at 10, rising toward 52.8.
#pragma once

namespace eyestream::retina {

double acuity_limit_cpd(double log_luminance);

// The log10 luminance at which the limit is `cpd` (below 52.8 c/deg).
double acuity_log_luminance(double cpd);

// The frequency (c/deg) a Gaussian blur of sigma_deg passes at 10 %
// contrast: exp(-2 pi^2 sigma^2 f^2) = 0.1.
double gaussian_cutoff_cpd(double sigma_deg);

}  // namespace eyestream::retina
