#include "retina/acuity_curve.hpp"

#include <cmath>

namespace eyestream::retina {

double acuity_limit_cpd(double log_l) { return 17.25 * std::atan(1.4 * log_l + 0.35) + 25.72; }

double acuity_log_luminance(double cpd) { return (std::tan((cpd - 25.72) / 17.25) - 0.35) / 1.4; }

double gaussian_cutoff_cpd(double sigma_deg) { return std::sqrt(std::log(10.0) / (2.0 * M_PI * M_PI)) / sigma_deg; }

}  // namespace eyestream::retina
