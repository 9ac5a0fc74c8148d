// The eye's aperture as a wave meets it (after Ritschel et al. 2009,
// "Temporal Glare", Eurographics): the pupil, the lens fibres and the
// particles of the lens and the vitreous, each a pure function of the
// viewer's seed. A light seen at an angle alpha from the eye's axis passes
// a particle at depth z behind the pupil z tan(alpha) off its place, so
// each light meets its own arrangement; the vitreous particles drift.
//
// The elements (this project's choices where the sources give no number):
//   lens fibres: a weak phase grating of period 10.5 um across the fibres
//     (the lenticular halo's ring at lambda / p, 3.0 deg at 550 nm; Spencer
//     et al. 1995 place it at 3 deg at 568 nm), the fibres running
//     radially, in bands 40 um wide (fibres are laid in growth shells),
//     each holding a whole number of fibres round its circle, 2 pi r / p
//     rounded, at its own random angle; peak phase 0.05 rad (weak: its ring is the
//     same for every pupil and light, the particles' speckle is not);
//   particles: 120 in the lens (depth 0.5-4 mm, radius 3-8 um) and 60 in
//     the vitreous (4-16 mm, 5-15 um), opaque, over an 8 mm disc; the
//     vitreous ones drift at up to 0.02 mm/s.
//   the upper eyelid (when the viewer's margin reflex distance MRD1 is
//     given: the lid margin that far above the pupil's centre; about 4-5
//     mm in an open eye, 1-2 mm squinting or with a drooping lid): opaque
//     above its margin, which lies 3.5 mm in front of the pupil (on the
//     cornea), and its lashes, 4 per mm of margin over 12 mm in two rows
//     (the lid holds 90-160 in 2-3 rows), each 8-11 mm long and 0.07-0.12
//     mm thick, leaving the margin forward and 10-25 deg downward and
//     curling up to 20-45 deg upward at its tip: they sag up to 1.3 mm
//     below the margin into the opening, further for a light above the gaze.
//     Edges of the lid and the lashes cut the wave like the pupil's rim:
//     their diffraction is the streaks across them (the lid's vertical,
//     the hanging lashes' horizontal) (Nakamae et al. 1990,
//     "A lighting model aiming at drive simulators", SIGGRAPH; Kakimoto et
//     al. 2004; Ritschel et al. 2009). The lower lid is not modelled.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace eyestream::glare {

struct WaveParticle {
  double x_mm, y_mm;    // on the pupil plane, seen along the axis, at t = 0
  double depth_mm;      // behind the pupil
  double radius_mm;
  double vx_mm_s, vy_mm_s;  // drift
};

// An eyelash: a curve leaving the lid margin at root_x_mm (the margin at
// -MRD1, y pointing down), depth root_depth_mm (negative: in front of the
// pupil); along its forward run s (0..forward_mm) it lies at
// x = root_x + s tan(side), y = -MRD1 + s tan(droop) - curl s^2.
struct WaveLash {
  double root_x_mm, root_depth_mm;
  double forward_mm;
  double tan_side, tan_droop, curl_per_mm;
  double width_mm;
};

struct WaveAperture {
  std::vector<WaveParticle> particles;
  std::vector<double> band_offsets;  // fibre bands' phase offsets (rad), one per 40 um of radius
  double eyelid_mrd1_mm = 0.0;       // the upper lid's margin above the pupil's centre; 0: no lid
  std::vector<WaveLash> lashes;      // (with a lid)
  static constexpr double kLidDepth_mm = -3.5;
  // The field as drawn (aperture_field): its side, samples per side, and
  // what does not change from frame to frame (the shrunk disc with its
  // soft rim and the fibres' phase; CV_64FC2).
  double side_mm = 0.0;
  int samples = 0;
  cv::Mat fixed;
  static constexpr double kFibrePeriod_mm = 0.0105;
  static constexpr double kFibreBand_mm = 0.04;
  double fibre_phase_rad = 0.05;
};

// The viewer's elements, drawn on samples x samples over side_mm; the
// upper lid and its lashes when eyelid_mrd1_mm > 0 (the rest is the same
// with or without them).
WaveAperture wave_aperture(std::int64_t seed, double side_mm, int samples, double eyelid_mrd1_mm = 0.0);

// What the aperture depends on from frame to frame.
struct WaveState {
  double pupil_mm = 4.0;
  double time_s = 0.0;
  double light_x_deg = 0.0, light_y_deg = 0.0;  // the light's direction from the eye's axis
};

// The aperture as the wave pattern draws it (wave_pattern.hpp): the
// aperture's samples x samples field (CV_64FC2) of side side_mm holding the pupil shrunk to a disc of
// diameter side_mm / 2: the particles' places (and their drift and depth
// parallax) scaled by that disc's diameter over the pupil's, their sizes
// and the fibres' period kept, so the particles' diffraction and the
// fibres' ring keep their true angles while the speckle between them is
// drawn coarser (wave_pattern.hpp says why). The pupil is apodised by the
// Stiles-Crawford effect (amplitude 10^(-0.025 r^2), r in mm of the true
// pupil; Stiles and Crawford 1933, Applegate and Lakshminarayanan 1993)
// and its rim softened over its last 5 %. The lid and the lashes, seen
// along the light as the particles are, are drawn as a true picture
// shrunk with the pupil, places and thickness alike (4 lashes per mm of
// 0.07-0.12 mm each kept with their places would merge into a band at
// the shrunk scale): they block their true share of the opening, and a
// lash's own streak is as much wider than a real lash's as the pupil was
// shrunk. Edges are softened over a sample.
cv::Mat aperture_field(const WaveAperture& a, const WaveState& s);

}  // namespace eyestream::glare
