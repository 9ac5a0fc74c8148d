#include "glare/pupil_dynamics.hpp"

#include <cmath>

namespace eyestream::glare {

double pupil_step(double pupil_mm, double target_mm, double dt_s, const PupilDynamics& p) {
  if (!(dt_s > 0.0)) return pupil_mm;
  const double tau = target_mm < pupil_mm ? p.constrict_tau_s : p.dilate_tau_s;
  if (!(tau > 0.0)) return target_mm;
  return target_mm + (pupil_mm - target_mm) * std::exp(-dt_s / tau);
}

}  // namespace eyestream::glare
