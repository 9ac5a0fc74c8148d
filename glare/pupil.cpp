#include "glare/pupil.hpp"

#include <algorithm>
#include <cmath>

namespace eyestream::glare {

double moon_spencer_pupil_mm(double log_l) { return 4.9 - 3.0 * std::tanh(0.4 * (log_l + 1.0)); }

double watson_yellott_pupil_mm(double l, double area, double age, int eyes) {
  const double flux = l * area * (eyes == 1 ? 0.1 : 1.0);
  const double x = std::pow(flux / 846.0, 0.41);
  const double stanley_davies = 7.75 - 5.75 * x / (x + 2.0);
  return stanley_davies + (std::clamp(age, 20.0, 83.0) - 28.58) * (0.02132 - 0.009562 * stanley_davies);
}

double pupil_mm(const ViewerProfile& viewer, double log_l, double frame_area_deg2) {
  if (viewer.pupil == PupilModel::moon_spencer) return moon_spencer_pupil_mm(log_l);
  const double area =
      viewer.pupil_field_deg > 0 ? M_PI * std::pow(viewer.pupil_field_deg / 2.0, 2.0) : frame_area_deg2;
  return watson_yellott_pupil_mm(std::pow(10.0, log_l), area, viewer.age_years);
}

}  // namespace eyestream::glare
