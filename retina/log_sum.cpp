#include "retina/log_sum.hpp"

#include <cstdint>

#include "retina/vector_clones.hpp"

namespace eyestream::retina {

namespace {

constexpr int kLanes = 8;

// log2(v) of a positive finite float, as above. Through double, so a
// subnormal float is a normal number here. Integer arithmetic on the bits
// only, no branch or select (which AVX2 loops would not vectorise): the
// bits less those of sqrt(1/2) carry the exponent e in their top twelve
// bits (two's complement) and m's bits below.
inline double log2_of(float v) {
  constexpr std::uint64_t kMantissa = 0x000fffffffffffffull;
  constexpr std::uint64_t kSqrtHalf = 0x3fe6a09e667f3bcdull;  // sqrt(1/2)
  const std::uint64_t offset = __builtin_bit_cast(std::uint64_t, double(v)) - kSqrtHalf;
  const double m = __builtin_bit_cast(double, (offset & kMantissa) + kSqrtHalf);  // in [sqrt(1/2), sqrt(2))
  // e + 2048 in [0, 4096), made a double by placing it in the mantissa of
  // 2^52 and taking 2^52 away (exact).
  const std::uint64_t biased = ((offset >> 52) + 2048u) & 4095u;
  const double e = (__builtin_bit_cast(double, 0x4330000000000000ull | biased) - 4503599627370496.0) - 2048.0;
  const double s = (m - 1.0) / (m + 1.0), s2 = s * s;
  double series = 1.0 / 17.0;
  series = series * s2 + 1.0 / 15.0;
  series = series * s2 + 1.0 / 13.0;
  series = series * s2 + 1.0 / 11.0;
  series = series * s2 + 1.0 / 9.0;
  series = series * s2 + 1.0 / 7.0;
  series = series * s2 + 1.0 / 5.0;
  series = series * s2 + 1.0 / 3.0;
  series = series * s2 + 1.0;
  constexpr double kTwoOverLn2 = 2.8853900817779268;  // 2 / ln 2
  return e + kTwoOverLn2 * s * series;
}

}  // namespace

EYESTREAM_VECTOR_CLONES
double log2_sum(const float* v, int n) {
  // A block of logs at a time (a loop the compiler runs as vectors), then
  // the block into the partial sums.
  constexpr int kBlock = 256;
  double logs[kBlock];
  double lanes[kLanes] = {};
  for (int start = 0; start < n; start += kBlock) {
    const int count = n - start < kBlock ? n - start : kBlock;
    for (int i = 0; i < count; ++i) logs[i] = log2_of(v[start + i]);
    int i = 0;
    for (; i + kLanes <= count; i += kLanes)
      for (int k = 0; k < kLanes; ++k) lanes[k] += logs[i + k];
    for (int k = 0; i < count; ++i, ++k) lanes[k] += logs[i];
  }
  double total = 0.0;
  for (double s : lanes) total += s;
  return total;
}

}  // namespace eyestream::retina
