#include "retina/adaptation.hpp"

#include <algorithm>

namespace eyestream::retina {

double adaptation_step(double a, double target, double dt_s, const AdaptationParams& p) {
  dt_s = std::max(dt_s, 0.0);
  if (a < target) return std::min(a + p.rate_up_log_per_s * dt_s, target);    // Jacobs et al. 2015 eq. 3, first case
  if (a > target) return std::max(a - p.rate_down_log_per_s * dt_s, target);  // Jacobs et al. 2015 eq. 3, second case
  return a;
}

}  // namespace eyestream::retina
