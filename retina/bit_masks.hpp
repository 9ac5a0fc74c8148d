// Choices made with masks of bits instead of branches. A loop whose body
// branches is not vectorised by GCC (its loads may not be made ahead of
// the test), while a select of two values computed anyway is. Used by the
// row loops compiled for AVX-512 and AVX2 (vector_clones.hpp).
#pragma once

#include <cstdint>
#include <cstring>

namespace eyestream::retina {

inline std::uint32_t bits_of(float v) {
  std::uint32_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

inline float float_of(std::uint32_t b) {
  float v;
  std::memcpy(&v, &b, sizeof v);
  return v;
}

// All ones when c, else 0.
inline std::uint32_t mask_if(bool c) { return 0u - std::uint32_t(c); }

// a where mask is all ones, b where it is 0.
inline float pick(std::uint32_t mask, float a, float b) { return float_of((bits_of(a) & mask) | (bits_of(b) & ~mask)); }

// Neither NaN nor infinite: an exponent other than all ones.
inline bool finite_bits(float v) { return (bits_of(v) & 0x7f800000u) != 0x7f800000u; }

}  // namespace eyestream::retina
