// Pupil diameter from the adapting luminance (docs/model.md).
#pragma once

#include "glare/viewer.hpp"

namespace eyestream::glare {

// Moon and Spencer (Spencer et al. 1995): D = 4.9 - 3 tanh(0.4 (log10 L + 1)) mm for a
// field luminance of 10^log_l cd/m^2: about 7.9 mm in the dark, 2.9 mm at
// 10 cd/m^2, 1.9 mm in sunlight.
double moon_spencer_pupil_mm(double log_l);

// Watson and Yellott's unified formula (J. Vision 12(10):12, 2012, eq. 21)
// for a field of luminance l (cd/m^2) and area (deg^2) seen with `eyes`
// (1 or 2) eyes by a viewer of age_years (clamped to the formula's 20-83):
//   F = l area M, M = 1 for two eyes and 0.1 for one,
//   D_SD = 7.75 - 5.75 (F/846)^0.41 / ((F/846)^0.41 + 2)   (Stanley-Davies)
//   D = D_SD + (age - 28.58) (0.02132 - 0.009562 D_SD).
double watson_yellott_pupil_mm(double l_cd_m2, double field_area_deg2, double age_years, int eyes = 2);

// The viewer's pupil at an adaptation level of 10^log_l cd/m^2 by the
// viewer's pupil model; frame_area_deg2 is the field when the viewer names
// none (Watson-Yellott only).
double pupil_mm(const ViewerProfile& viewer, double log_l, double frame_area_deg2);

}  // namespace eyestream::glare
