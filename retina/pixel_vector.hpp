// A three-channel float pixel and one more float as one vector (GCC's and
// Clang's vector extension: SSE on x86-64, NEON on AArch64), so that a
// pixel's three values take one instruction where a loop over values
// would be vectorised narrowly or not at all (stride-3 reads). Loaded from
// and stored to any float: four floats where the fourth is in bounds (the
// next pixel's first value, rewritten by that pixel when stored), else
// three.
#pragma once

#include <cstring>

namespace eyestream::retina {

typedef float PixelVector __attribute__((vector_size(16)));
typedef float LoosePixelVector __attribute__((vector_size(16), aligned(4)));

inline PixelVector four_floats(const float* p) { return *reinterpret_cast<const LoosePixelVector*>(p); }

inline PixelVector three_floats(const float* p) {
  PixelVector v = {0, 0, 0, 0};
  std::memcpy(&v, p, 3 * sizeof(float));
  return v;
}

inline void store_four(float* p, PixelVector v) { *reinterpret_cast<LoosePixelVector*>(p) = v; }

inline void store_three(float* p, PixelVector v) { std::memcpy(p, &v, 3 * sizeof(float)); }

}  // namespace eyestream::retina
