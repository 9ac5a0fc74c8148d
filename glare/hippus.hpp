// Hippus: the pupil's unrest, a fluctuation of its diameter with no change
// of light (Stark, Campbell and Atwood 1958, "Pupil unrest: an example of
// noise in a biological servomechanism", Nature 182). What this project
// uses, and why:
//   - the spectrum: power falling as 1/f from 0.05 to 1.5 Hz and nothing
//     outside; the pupil's own response rolls off above about 1.6 Hz
//     (Stark's pupil transfer function, a 0.1 s third-order lag), and the
//     slow drifts below 0.05 Hz are the adaptation model's;
//   - the size: an RMS of 0.1 mm at a 4 mm pupil, within the standard
//     deviations of 0.04 to 0.2 mm of the hippus of Ritschel et al. 2009
//     ("Temporal Glare", Computer Graphics Forum 28(2), eq. 1), scaled
//     with the pupil by their factor (p_max / p) sqrt(1 - p / p_max),
//     p_max = 9 mm: larger for small pupils, none at full dilation.
// The noise is a sum of 200 sinusoids at log-spaced frequencies over the
// band (equal amplitudes give the 1/f density) with phases from the
// viewer's seed: a pure function of the seed and the time, so the same
// seed gives the same film and a checkpoint needs no state.
#pragma once

#include <cstdint>
#include <vector>

namespace eyestream::glare {

class Hippus {
 public:
  static constexpr double kLowHz = 0.05, kHighHz = 1.5;
  static constexpr double kRmsAt4mm_mm = 0.1;
  static constexpr double kMaxPupil_mm = 9.0;

  explicit Hippus(std::int64_t seed);
  // The unit-RMS noise at t seconds.
  double noise(double t_s) const;
  // The change of a pupil of pupil_mm at t seconds (mm).
  double offset_mm(double pupil_mm, double t_s) const;
  // The RMS of that change for a pupil of pupil_mm.
  static double rms_mm(double pupil_mm);

 private:
  std::vector<double> hz_, phase_;
};

}  // namespace eyestream::glare
