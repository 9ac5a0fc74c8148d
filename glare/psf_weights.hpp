// The weights of the Vos components f0..f3 for a viewer at an adaptation
// level (Spencer et al. 1995 eqs. 9-10).
#pragma once

#include <array>

#include "glare/viewer.hpp"

namespace eyestream::glare {

struct PsfWeights {
  double core = 0, inner = 0, outer = 0, halo = 0;  // weights of f0, f1, f2, f3; they sum to 1
};

// Weights for each channel of an image (R, G, B): the engines take one set
// for all three, or one each (the glare stage's set-up spreads the core,
// inner and outer components in one pass, one per channel).
using ChannelWeights = std::array<PsfWeights, 3>;

inline ChannelWeights same_in_every_channel(const PsfWeights& w) { return {w, w, w}; }

// Photopic, mesopic and scotopic weights (Spencer et al. 1995 eq. 9):
//   Pp = 0.384 f0 + 0.478 f1 + 0.138 f2
//   Pm = 0.368 f0 + 0.478 f1 + 0.138 f2 + 0.016 f3
//   Ps = 0.282 f0 + 0.478 f1 + 0.207 f2 + 0.033 f3
// blended piecewise-linearly in log adaptation luminance: Ps at and below
// 0.01 cd/m^2, Pm at the log-middle of the mesopic range (0.17 cd/m^2), Pp
// at and above 3 cd/m^2, so glare never pops between frames (docs/model.md).
// The halo needs a pupil wider than about 3 mm (the lens fibres sit behind
// the iris otherwise): its weight is ramped by smoothstep((D - 2.5 mm) /
// 1 mm), and what it loses goes back to the core. Then the age term moves
// 6.9e-9 A^4 from f0 to f2 (Spencer et al. 1995 eq. 10; at most 90 % of the core), and
// haze moves its share of what is left of the core the same way (Matsuda and Ikedo:
// haze adds bloom). The weights are never negative and sum
// to 1; no component is renormalised.
PsfWeights psf_weights(const ViewerProfile& viewer, double adaptation_log, double pupil_mm);

}  // namespace eyestream::glare
