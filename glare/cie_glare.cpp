#include "glare/cie_glare.hpp"

#include <algorithm>
#include <cmath>

#include "glare/vos_psf.hpp"

namespace eyestream::glare {

namespace {
constexpr double kInnermostDeg = 0.1;  // the equation's validity starts here
}

double cie_general_glare(double t, double age, double p) {
  const double aging = 1.0 + std::pow(age / 62.5, 4.0);
  return 10.0 / (t * t * t) + (5.0 / (t * t) + 0.1 * p / t) * aging + 0.0025 * p;
}

double CieScatter::density(double t) const {
  return cie_general_glare(std::max(t, kInnermostDeg), age_years, pigmentation) / scattered_share;
}

CieScatter cie_scatter(double age, double p) {
  CieScatter s{age, p, 1.0};
  s.scattered_share = hemisphere_integral([&](double t) { return s.density(t); });
  return s;
}

}  // namespace eyestream::glare
