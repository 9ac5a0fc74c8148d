// The fine structure of the PSF by wave optics (after Ritschel et al.
// 2009, "Temporal Glare", Computer Graphics Forum 28(2)): the Fraunhofer
// diffraction of the viewer's aperture (wave_aperture.hpp) as this light
// meets it, through the colour-matching functions, as a modulation of the
// macroscopic PSF (Vos's or the CIE's) that keeps its radial profile.
//
// One FFT of 512 x 512 samples over a 1.58 mm field gives the far field at
// 550 nm in bins of 0.02 deg. The true speckle between the aperture's
// elements is far finer than a pixel (lambda / D = 0.008 deg for a 4 mm
// pupil): a pixel would average it away, while the eye, fixating a light,
// resolves it as the corona's needles and sees them shimmer. So, as
// Ritschel et al. draw the aperture at the screen's scale, the pupil's
// layout is shrunk into a 0.79 mm disc (the particles' places scaled, their
// sizes and the fibres' period kept): the particles' diffraction (the
// corona's extent) and the fibres' ring (the halo's radius) keep their true
// angles, and the speckle between them is drawn about a pixel wide (0.04
// deg). It changes as the true speckle does: with the pupil (every place
// rescales), with the light's direction (particles at different depths
// shift against each other) and as the vitreous drifts.
//
// The pattern at wavelength lambda is the 550 nm one scaled in angle by
// lambda / 550 nm (and in intensity by (550 nm / lambda)^2); 16 wavelengths
// from 400 to 700 nm weighted by each display channel's colour-matching
// function give R, G and B, whose specks smear radially into needles, blue
// inside red. A pixel's value is the pattern averaged over its footprint,
// and each 1 px ring about the centre is scaled to mean 1 (within 3 px: 1),
// so the PSF it multiplies keeps every ring's energy.
#pragma once

#include <opencv2/core.hpp>

#include "glare/wave_aperture.hpp"

namespace eyestream::glare {

struct WavePattern {
  cv::Mat rgb[3];  // CV_64F, (2 radius + 1) squared, centred; each 1 px ring's mean is 1
  int radius = 0;  // px
  double pixels_per_degree = 0.0;
};

// The field: kWaveSamples samples a side over wave_field_mm(), giving the
// far field at kWaveLambda0_nm in bins of kWaveBin_deg.
inline constexpr int kWaveSamples = 512;
inline constexpr double kWaveLambda0_nm = 550.0, kWaveBin_deg = 0.02;
inline double wave_field_mm() { return kWaveLambda0_nm * 1e-6 / (kWaveBin_deg * 3.14159265358979323846 / 180.0); }
// The viewer's aperture on that field.
inline WaveAperture viewer_aperture(std::int64_t seed, double eyelid_mrd1_mm = 0.0) {
  return wave_aperture(seed, wave_field_mm(), kWaveSamples, eyelid_mrd1_mm);
}

// The largest angle the pattern reaches at every wavelength (deg).
inline constexpr double kWavePatternReach_deg = 3.6;

// The pattern for this state at pixels_per_degree, out to radius_px
// (at most kWavePatternReach_deg; beyond it the modulation is 1).
WavePattern wave_pattern(const WaveAperture& aperture, const WaveState& state, double pixels_per_degree,
                         int radius_px);

// The Pearson correlation of two patterns' modulations (value - 1) over the
// rings from inner_deg to outer_deg, channel G.
double pattern_correlation(const WavePattern& a, const WavePattern& b, double inner_deg, double outer_deg);

}  // namespace eyestream::glare
