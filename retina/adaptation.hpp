// Global adaptation: the log luminance the viewer is adapted to moves toward
// a target at fixed rates (Jacobs et al. 2015 eq. 3).
#pragma once

namespace eyestream::retina {

struct AdaptationParams {
  double rate_up_log_per_s = 0.75;   // a1, toward brighter (Jacobs et al. 2015 App. A)
  double rate_down_log_per_s = 0.2;  // a2, toward darker (Jacobs et al. 2015 App. A)
};

// One step of duration dt_s >= 0 from adaptation A (log10 cd/m^2) toward
// target AT: A + a1 dt below the target, A - a2 dt above, never overshooting
// (Jacobs et al. 2015 eq. 3). Exact for any dt, including 0 and very long steps.
double adaptation_step(double adaptation_log, double target_log, double dt_s, const AdaptationParams& p);

}  // namespace eyestream::retina
