// The viewer's optics: who is looking and how wide their pupil is at an
// adaptation level (MODEL.md 1.2).
#pragma once

namespace eyestream::glare {

struct ViewerProfile {
  double age_years = 25.0;
};

// Moon and Spencer pupil diameter (mm) for a field luminance of 10^log_l
// cd/m^2: D = 4.9 - 3 tanh(0.4 (log10 L + 1)) (seed 000; MODEL.md 1.2):
// about 7.9 mm in the dark, 2.9 mm at 10 cd/m^2, 1.9 mm in sunlight.
double pupil_diameter_mm(double log_l);

}  // namespace eyestream::glare
