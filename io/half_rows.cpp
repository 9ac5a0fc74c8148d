#include "io/half_rows.hpp"

#include <cstring>

#include "io/vector_clones.hpp"

namespace eyestream::io {

namespace {

// A half's value as a float. Normal: the exponent rebiased (15 to 127) and
// the mantissa moved up 13 bits. Subnormal (exponent 0): the mantissa
// times 2^-24, made from an integer (no subnormal float arises). Infinite
// or NaN (exponent 31): the float's all-ones exponent, the same mantissa
// bits. Each made, then one chosen: no branch in the loop.
inline float half_to_float(std::uint16_t h) {
  const std::uint32_t sign = std::uint32_t(h & 0x8000u) << 16;
  const std::uint32_t magnitude = h & 0x7fffu;
  const std::uint32_t exponent = magnitude >> 10;
  const std::uint32_t normal = (magnitude << 13) + (std::uint32_t(127 - 15) << 23);
  const std::uint32_t special = 0x7f800000u | ((magnitude & 0x3ffu) << 13);
  const float scaled = float(int(magnitude)) * 5.9604644775390625e-8f;  // 2^-24
  std::uint32_t small;
  std::memcpy(&small, &scaled, sizeof small);
  const std::uint32_t bits = (exponent == 0 ? small : (exponent == 31 ? special : normal)) | sign;
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace

EYESTREAM_VECTOR_CLONES
void halves_to_rgb(const std::uint16_t* __restrict red, const std::uint16_t* __restrict green,
                   const std::uint16_t* __restrict blue, float* __restrict rgb, int n) {
  for (int x = 0; x < n; ++x) {
    rgb[3 * x] = half_to_float(red[x]);
    rgb[3 * x + 1] = half_to_float(green[x]);
    rgb[3 * x + 2] = half_to_float(blue[x]);
  }
}

EYESTREAM_VECTOR_CLONES
void halves_to_grey_rgb(const std::uint16_t* __restrict grey, float* __restrict rgb, int n) {
  for (int x = 0; x < n; ++x) {
    const float v = half_to_float(grey[x]);
    rgb[3 * x] = rgb[3 * x + 1] = rgb[3 * x + 2] = v;
  }
}

}  // namespace eyestream::io
