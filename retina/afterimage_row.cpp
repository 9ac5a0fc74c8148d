#include "retina/afterimage_row.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "retina/photoreceptor.hpp"
#include "retina/vector_clones.hpp"

namespace eyestream::retina {

namespace {

constexpr int kBlockSites = 128;
constexpr int kBlock = 3 * kBlockSites;

// The gain alpha (local_gain) and the power table's argument: alpha or its
// inverse, whichever is at most 1 (PowTable::any); each site's visibility
// for each of its cones.
EYESTREAM_VECTOR_CLONES
void gains_and_visibility(const AfterimageTerms& k, const float* __restrict d, const float* __restrict r,
                          const float* __restrict visible, float* __restrict alpha, float* __restrict argument,
                          float* __restrict visibility, int sites) {
  const float c_max = float(k.c_max), epsilon = k.epsilon;
  for (int j = 0; j < 3 * sites; ++j) {
    const float a = local_gain<float>(d[j], r[j], c_max, epsilon);
    const float inverse = 1.0f / a;  // both made, then one chosen (cone_step_row.cpp)
    alpha[j] = a;
    argument[j] = a <= 1.0f ? a : inverse;
  }
  for (int s = 0; s < sites; ++s) visibility[3 * s] = visibility[3 * s + 1] = visibility[3 * s + 2] = visible[s];
}

// The terms from the powers q of the arguments.
EYESTREAM_VECTOR_CLONES
void terms(const AfterimageTerms& k, const float* __restrict b, const float* __restrict d,
           const float* __restrict b_inf, const float* __restrict alpha, const float* __restrict q,
           const float* __restrict visibility, float* __restrict gain, float* __restrict bleach, int n) {
  const double c_max = k.c_max, strength = k.strength;
  const bool with_gain = k.gain, with_bleach = k.bleach;
  for (int j = 0; j < n; ++j) {
    const float power = alpha[j] <= 1.0f ? q[j] : 1.0f / q[j];  // alpha^j2 (Jacobs et al. 2015 eqs. 11-12)
    const double g = with_gain ? double(power) : 1.0;
    // Jacobs et al. 2015 eq. 12: j1 (C / C_max) max(B - B_inf, 0)
    const double excess = double(b[j] - b_inf[j]);
    const double bleached = with_bleach ? strength * (1.0 - double(d[j]) / c_max) * (excess < 0.0 ? 0.0 : excess) : 0.0;
    gain[j] = float(double(visibility[j]) * (g - 1.0));
    bleach[j] = float(double(visibility[j]) * bleached);
  }
}

// The largest |value| of n floats, NaNs left out (as std::max leaves them
// out when they come after its first value): as integers, the magnitudes'
// bits order as the magnitudes do, and a NaN's are above infinity's.
EYESTREAM_VECTOR_CLONES
std::uint32_t largest_magnitude_bits(const float* __restrict v, int n) {
  std::uint32_t largest = 0;
  for (int j = 0; j < n; ++j) {
    std::uint32_t bits;
    std::memcpy(&bits, &v[j], sizeof bits);
    bits &= 0x7fffffffu;
    bits = bits > 0x7f800000u ? 0u : bits;
    largest = bits > largest ? bits : largest;
  }
  return largest;
}

}  // namespace

float afterimage_row(const AfterimageTerms& k, const float* b, const float* d, const float* b_inf, const float* r,
                     const float* visible, float* gain, float* bleach, int sites) {
  float alpha[kBlock], argument[kBlock], q[kBlock], visibility[kBlock], gain_block[kBlock], bleach_block[kBlock];
  std::uint32_t largest = 0;
  for (int start = 0; start < sites; start += kBlockSites) {
    const int count = std::min(kBlockSites, sites - start), n = 3 * count, at = 3 * start;
    gains_and_visibility(k, d + at, r + at, visible + start, alpha, argument, visibility, count);
    if (k.gain)
      k.power->batch(argument, q, n);
    else
      std::fill(q, q + n, 1.0f);
    terms(k, b + at, d + at, b_inf + at, alpha, q, visibility, gain_block, bleach_block, n);
    largest = std::max({largest, largest_magnitude_bits(gain_block, n), largest_magnitude_bits(bleach_block, n)});
    if (gain) std::copy(gain_block, gain_block + n, gain + at);
    if (bleach) std::copy(bleach_block, bleach_block + n, bleach + at);
  }
  float out;
  std::memcpy(&out, &largest, sizeof out);
  return out;
}

}  // namespace eyestream::retina
