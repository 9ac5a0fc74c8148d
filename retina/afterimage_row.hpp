// One row of the retinal grid's afterimage terms in float (Jacobs et al.
// 2015 eqs. 11-12; RetinaState::afterimages): the adaptation gain's excess
// alpha^j2 - 1 and the bleaching term j1 (C / C_max) max(B - B_inf, 0),
// each times the site's visibility, with the row's largest magnitude. A
// block of sites at a time through loops that run as vectors (AVX-512 and
// AVX2 versions beside the baseline, vector_clones.hpp), the power by its
// table's batch: the same values, in the same order, as one site at a time.
#pragma once

#include "retina/pow_table.hpp"

namespace eyestream::retina {

struct AfterimageTerms {
  bool gain = true, bleach = true;  // which terms (AfterimageOptions)
  double c_max = 1.0;               // C_max
  float epsilon = 0.01f;            // the gain's regulariser, a fraction of C_max (local_gain)
  double strength = 0.03;           // j1
  const PowTable* power = nullptr;  // x^j2
};

// For `sites` sites (three floats each, L M S) of bleaching b, deficit d,
// equilibrium b_inf, response r and one visibility each: the two terms
// into gain and bleach (three floats a site; either may be null: not
// written). Returns the largest |term| (NaNs left out, as the scalar
// loop's std::max leaves them out).
float afterimage_row(const AfterimageTerms& k, const float* b, const float* d, const float* b_inf, const float* r,
                     const float* visible, float* gain, float* bleach, int sites);

}  // namespace eyestream::retina
