// Counter-based random numbers: a pure function of (seed, stream, frame,
// x, y, channel), so results never depend on thread order or count.
#pragma once

#include <cstdint>

namespace eyestream::retina {

// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mix.
inline std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

inline std::uint64_t hash_key(std::uint64_t seed, std::uint64_t stream, std::uint64_t frame, std::uint64_t x,
                              std::uint64_t y, std::uint64_t channel) {
  std::uint64_t h = mix64(seed ^ 0x9e3779b97f4a7c15ULL);
  h = mix64(h ^ stream);
  h = mix64(h ^ frame);
  h = mix64(h ^ ((x << 32) | (y & 0xffffffffULL)));
  return mix64(h ^ channel);
}

// Uniform in [0, 1) with 24 random bits (exact in float).
inline float hash_uniform(std::uint64_t key) { return float(key >> 40) * (1.0f / 16777216.0f); }

// The k-th (0, 1, 2) of three uniforms in [0, 1) with 21 bits each, drawn
// from one 64-bit key: one hash serves the three channels of a pixel.
inline float hash_uniform3(std::uint64_t key, int k) {
  // (21 bits fit 32: a 32-bit conversion, which vector units have)
  return float(std::uint32_t((key >> (21 * k)) & 0x1fffffULL)) * (1.0f / 2097152.0f);
}

// The per-row part of hash_key for (seed, stream, frame, y); finish a pixel
// with hash_pixel(row_key, x). Equivalent in quality to hash_key.
inline std::uint64_t hash_row(std::uint64_t seed, std::uint64_t stream, std::uint64_t frame, std::uint64_t y) {
  std::uint64_t h = mix64(seed ^ 0x9e3779b97f4a7c15ULL);
  h = mix64(h ^ stream);
  h = mix64(h ^ frame);
  return mix64(h ^ (y * 0xd1b54a32d192ed03ULL));
}
inline std::uint64_t hash_pixel(std::uint64_t row_key, std::uint64_t x) {
  return mix64(row_key ^ (x * 0x8cb92ba72f3d8dd7ULL));
}

// Named streams, so two effects never share random numbers.
enum class RandomStream : std::uint64_t { kDither = 1, kAcuity = 2 };

}  // namespace eyestream::retina
