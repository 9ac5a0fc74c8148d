// e^x in float by a polynomial, with no call to the library: a loop that
// calls it runs as vectors, and gives the same bytes on every machine (no
// fused multiply-add, vector_clones.hpp). Cody and Waite's reduction
// x = n ln 2 + r, |r| <= ln(2)/2, with ln 2 split in two parts, and
// Moshier's degree-7 polynomial for e^r (the Cephes library's expf, 1989).
// Relative error under 1.5e-7 (8.1e-8 seen) for x in [-87.3, 88] (tests/exp_float_test.cpp);
// 0 below -87.3 (where e^x is under the least normal float) and for NaN,
// e^88 above 88.
// For the retina's per-site exact decays, whose exponents are <= 0.
#pragma once

#include <cstdint>

namespace eyestream::retina {

inline float exp_float(float x) {
  constexpr float kLeast = -87.33f;  // e^kLeast is just above the least normal float
  const bool under = !(x >= kLeast);  // and NaN: no float-to-int of a NaN below
  x = under ? kLeast : x;
  x = x > 88.0f ? 88.0f : x;
  // n = floor(x / ln 2 + 1/2), by truncation of a positive number.
  const int n = int(x * 1.44269504088896341f + 128.5f) - 128;
  const float fn = float(n);
  float r = x - fn * 0.693359375f;
  r = r - fn * -2.12194440e-4f;
  float p = 1.9875691500e-4f;
  p = p * r + 1.3981999507e-3f;
  p = p * r + 8.3334519073e-3f;
  p = p * r + 4.1665795894e-2f;
  p = p * r + 1.6666665459e-1f;
  p = p * r + 5.0000001201e-1f;
  p = p * (r * r) + r + 1.0f;
  const float two_to_n = __builtin_bit_cast(float, std::uint32_t(n + 127) << 23);
  return under ? 0.0f : p * two_to_n;
}

}  // namespace eyestream::retina
