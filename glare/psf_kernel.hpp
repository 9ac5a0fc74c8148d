// The eye's PSF on the pixel grid: one kernel per PSF component, each
// integrated over every pixel's footprint (Spencer et al. 1995 sec. 3.2, Yoshida et al. 2008;
// docs/model.md). The frame's kernel is the weighted sum of the components
// (psf_weights.hpp), so any weights (age, adaptation regime, pupil) combine
// without rebuilding anything.
//
// Departure from the model as specified (docs/model.md): the kernels are not renormalised to unit sum
// after truncation to the frame's reach. Each holds the PSF's own energy
// within that reach (the components have unit volume over the hemisphere,
// see vos_psf.hpp), and light scattered farther leaves the frame. Renor-
// malising would push the far tail of f2 back onto nearby offsets and
// inflate every veil: by about 25 % on a 16:9 frame (tests/report_test.cpp).
#pragma once

#include <opencv2/core.hpp>

#include "glare/eye_optics.hpp"
#include "glare/psf_weights.hpp"

namespace eyestream::glare {

struct ComponentKernels {
  // (2W - 1) x (2H - 1) for a W x H frame, centred at (W - 1, H - 1): a
  // light at one edge of the frame reaches the other edge. CV_64F each.
  cv::Mat core, inner, outer;  // f0, f1, f2
  cv::Mat halo[3];             // f3 for the R, G and B channels
  double pixels_per_degree = 0;
  cv::Point centre() const { return {core.cols / 2, core.rows / 2}; }
};

// Builds the component kernels for a frame_width x frame_height frame.
// Each pixel's value is the PSF (per steradian) integrated over its
// footprint (solid angle (pi / 180 / ppd)^2; angles from
// pixel centres to the PSF centre at pixels_per_degree), sampled 16x16
// within 3 px of the centre, 4x4 within 12 px and on the halo ring (2-4.5
// deg), at the pixel centre elsewhere. The halo of channel c mixes f3 over
// 50 wavelengths from 400 to 700 nm weighted by the channel's colour-
// matching function (color_matching.hpp): blue rings sit inside red ones.
// The core, inner and outer kernels hold the optics' components (Vos f0,
// f1, f2, or the CIE scattered part in the inner slot, eye_optics.hpp);
// with flare lines on, the inner, outer and halo kernels carry them
// (flare_lines.hpp) with every 1 px ring's energy unchanged.
ComponentKernels build_component_kernels(int frame_width, int frame_height, double pixels_per_degree,
                                         const EyeOptics& optics = EyeOptics());

// The combined kernel of channel c for given weights (sum of weighted
// components), CV_64F; it sums to the PSF's energy within the frame's reach.
cv::Mat combined_kernel(const ComponentKernels& k, const PsfWeights& w, int channel);

// Share of the continuous PSF's energy beyond t_deg (Spencer et al. 1995 states
// about 0.36 beyond 0.05 deg at age 20, 0.45 at age 60), at 568 nm.
double energy_beyond(const PsfWeights& w, double t_deg);

}  // namespace eyestream::glare
