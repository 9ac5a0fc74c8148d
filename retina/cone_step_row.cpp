#include "retina/cone_step_row.hpp"

#include "retina/bit_masks.hpp"
#include "retina/exp_float.hpp"
#include "retina/vector_clones.hpp"

namespace eyestream::retina {

namespace {

constexpr int kBlockSites = 128;
constexpr int kBlock = 3 * kBlockSites;

// The stimulus (0 unless finite and positive) and the power table's
// argument: sigma / I or its inverse, whichever is at most 1
// (ToneCurve::response).
EYESTREAM_VECTOR_CLONES
void stimulus_and_ratio(const float* __restrict s, float sigma, float* __restrict intensity,
                        float* __restrict ratio_or_inverse, int n) {
  for (int j = 0; j < n; ++j) {
    const float v = s[j];
    const float i = pick(mask_if((v > 0.0f) & finite_bits(v)), v, 0.0f);
    const float ratio = sigma / i;       // +inf at 0: its inverse is 0
    const float inverse = 1.0f / ratio;  // both made, then one chosen: a loop with a
                                         // division in a branch is not run as vectors
    intensity[j] = i;
    // 0 for no stimulus (its response is 0 whatever the table says): the
    // table is read only in [0, 1], whatever sigma is.
    ratio_or_inverse[j] = i > 0.0f ? (ratio <= 1.0f ? ratio : inverse) : 0.0f;
  }
}

// The step itself, with q = the table's power of ratio_or_inverse. The
// arrays do not overlap (__restrict: without it GCC 12 does not run the
// loop as vectors).
EYESTREAM_VECTOR_CLONES
void step_block(const ConeStep& k, const float* __restrict b1, const float* __restrict b2,
                const float* __restrict intensity, const float* __restrict q, float* __restrict b_inf,
                float* __restrict response, float* __restrict b, float* __restrict d, int n) {
  const float sigma = k.sigma, dt = k.dt, decay = k.calcium_decay, c_max = k.c_max;
  for (int j = 0; j < n; ++j) {
    const float i = intensity[j];
    const float ratio = sigma / i;
    const float below = 1.0f / (1.0f + q[j]), above = q[j] / (q[j] + 1.0f);  // both, as above
    const float r = i > 0.0f ? (ratio <= 1.0f ? below : above) : 0.0f;
    const float rate = b1[j] * i + b2[j];
    const float rest = b1[j] * i / rate;  // Jacobs et al. 2015 eq. 6
    b_inf[j] = rest;
    response[j] = r;
    // eq. 5, clamped to [0, 1] as std::clamp does
    const float stepped = (b[j] - rest) * exp_float(-rate * dt) + rest;
    b[j] = stepped < 0.0f ? 0.0f : (1.0f < stepped ? 1.0f : stepped);
    const float d_inf = c_max * r;                         // eq. 10 as a deficit
    const float settled = (d[j] - d_inf) * decay + d_inf;  // eq. 9
    d[j] = settled < 0.0f ? 0.0f : (c_max < settled ? c_max : settled);
  }
}

}  // namespace

void step_cone_row(const ConeStep& k, const float* s, float* b_inf, float* response, float* b, float* d, int sites) {
  float b1[kBlock], b2[kBlock], intensity[kBlock], x[kBlock], q[kBlock];
  for (int j = 0; j < kBlock; ++j) {
    b1[j] = k.bleach_rate[j % 3];
    b2[j] = k.regen_rate[j % 3];
  }
  for (int start = 0; start < sites; start += kBlockSites) {
    const int n = 3 * (sites - start < kBlockSites ? sites - start : kBlockSites), at = 3 * start;
    stimulus_and_ratio(s + at, k.sigma, intensity, x, n);
    k.power->batch(x, q, n);
    step_block(k, b1, b2, intensity, q, b_inf + at, response + at, b + at, d + at, n);
  }
}

}  // namespace eyestream::retina
