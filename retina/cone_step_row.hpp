// One row of the retinal grid's sites stepped in float: each site's three
// cones (L, M, S) at a constant stimulus for dt, exactly (Jacobs et al.
// 2015 eqs. 1, 5, 6, 9 and 10; photoreceptor.hpp), with the equilibrium
// they relax toward written on the way. A row at a call, a block of sites
// at a time through loops that run as vectors (AVX-512 and AVX2 versions
// beside the baseline, vector_clones.hpp): the tone curve's power by its
// table (PowTable::batch) and e^x by exp_float.hpp, the only difference
// from the scalar formula (relative 1.5e-7 in the decay factor).
#pragma once

#include "retina/photoreceptor.hpp"
#include "retina/pow_table.hpp"

namespace eyestream::retina {

struct ConeStep {
  float bleach_rate[3], regen_rate[3];  // b1, b2 per cone
  float dt;                             // s
  float calcium_decay;                  // e^(-c2 dt)
  float c_max;
  float sigma;            // the tone curve's half-response luminance
  const PowTable* power;  // its x^n
};

// For `sites` sites (three floats each): stimulus s (non-finite or
// negative counts as 0), bleaching b and calcium deficit d stepped in
// place, b_inf and response written.
void step_cone_row(const ConeStep& k, const float* s, float* b_inf, float* response, float* b, float* d, int sites);

}  // namespace eyestream::retina
