#include "glare/vos_psf.hpp"

#include <cmath>

namespace eyestream::glare {

double vos_f0(double t) { return 2.61e6 * std::exp(-(t / 0.02) * (t / 0.02)); }  // Spencer et al. 1995 eq. 5

double vos_f1(double t) { return 20.91 / std::pow(t + 0.02, 3.0); }  // Spencer et al. 1995 eq. 6

double vos_f2(double t) { return 72.37 / std::pow(t + 0.02, 2.0); }  // Spencer et al. 1995 eq. 7

double vos_f3(double t, double lambda) {  // Spencer et al. 1995 eq. 8 (Hemenger)
  const double d = t - 3.0 * lambda / 568.0;
  return 436.9 * (568.0 / lambda) * std::exp(-19.75 * d * d);
}

double hemisphere_integral(const std::function<double(double)>& f, int samples) {
  // Midpoint rule in s with u = (pi/2) s^3: samples crowd toward u = 0.
  const double half_pi = M_PI / 2.0;
  double sum = 0.0;
  for (int i = 0; i < samples; ++i) {
    const double s = (i + 0.5) / samples;
    const double u = half_pi * s * s * s;
    const double du = half_pi * 3.0 * s * s / samples;
    sum += f(u * 180.0 / M_PI) * std::sin(u) * du;
  }
  return 2.0 * M_PI * sum;
}

}  // namespace eyestream::glare
