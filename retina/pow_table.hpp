// x^p for x in [0, 1] by table: linear interpolation between 1024 points
// per octave of x (its float exponent and top ten mantissa bits), for x
// down to 2^-40, std::pow below. Relative error under 1e-7 (the
// interpolation's, about p (1 - p) 2^-23; tests/pow_table_test.cpp), some
// 10x faster than std::pow per value. For per-pixel powers with a fixed
// exponent: the display gamma.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace eyestream::retina {

class PowTable {
 public:
  explicit PowTable(double exponent);

  // x^p; x is clamped to [0, 1] by the caller.
  float operator()(float x) const {
    std::uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    bits &= 0x7fffffffu;  // -0 as 0 (its sign bit would index past the table)
    const int octave = int(bits >> 23) - 127 + kOctaves;  // x in [2^(octave - 40), 2^(octave - 39))
    if (octave < 0) return x > 0.0f ? float(std::pow(double(x), exponent_)) : 0.0f;
    const std::uint32_t i = std::uint32_t(octave) * kSteps + ((bits >> 13) & (kSteps - 1));
    const float f = float(bits & 8191u) * (1.0f / 8192.0f);
    float at, step;
    split(entries_[i], at, step);
    return at + f * step;
  }

  // y[i] = x[i]^p for n values in [0, 1], exactly as operator() gives
  // them: a row at a call, compiled for AVX-512 and AVX2 beside the baseline
  // (vector_clones.hpp), the table read by vector gathers (one 64-bit
  // gather per value: a point and its step to the next). x and y must not
  // overlap.
  void batch(const float* x, float* y, int n) const;

  // x^p for any x >= 0: above 1 as 1 / (1/x)^p.
  float any(float x) const { return x <= 1.0f ? (*this)(x) : 1.0f / (*this)(1.0f / x); }

 private:
  static constexpr int kOctaves = 40, kSteps = 1024;
  // Each point's value and its step to the next point (the float
  // difference, as the interpolation would take it), in one 64-bit entry.
  static std::uint64_t entry(float at, float step);
  static void split(std::uint64_t e, float& at, float& step) {
    const std::uint32_t lo = std::uint32_t(e), hi = std::uint32_t(e >> 32);
    std::memcpy(&at, &lo, sizeof at);
    std::memcpy(&step, &hi, sizeof step);
  }

  double exponent_;
  std::vector<std::uint64_t> entries_;
};

// The table for `exponent`, built on first use and kept for the run (a run
// uses one or two exponents). Thread-safe.
const PowTable& shared_pow_table(double exponent);

}  // namespace eyestream::retina
