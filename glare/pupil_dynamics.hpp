// The pupil's own time course: it follows the field luminance (Moon and
// Spencer 1944; Watson and Yellott 2012) with a first-order lag, fast when
// it constricts and slow when it dilates. Ellis (1981, "The pupillary light
// reflex in normal subjects", Br. J. Ophthalmol. 65) reports constriction
// largely complete within about a second of a step of light and redilation
// taking several seconds; the time constants below (0.2 s and 1.5 s) are
// this project's choice within those observations.
#pragma once

namespace eyestream::glare {

struct PupilDynamics {
  double constrict_tau_s = 0.2;
  double dilate_tau_s = 1.5;
};

// The pupil diameter after dt_s seconds toward `target_mm` from `pupil_mm`
// (exact for a constant target, so any dt is stable and frame rate does
// not matter).
double pupil_step(double pupil_mm, double target_mm, double dt_s, const PupilDynamics& p);

}  // namespace eyestream::glare
