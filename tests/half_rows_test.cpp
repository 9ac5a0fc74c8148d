// The half-float rows (io/half_rows.hpp) against Imath's own conversion of
// every one of the 65536 halves, bit for bit (zeros of both signs,
// subnormals, infinities, NaNs with their payloads), in each channel and
// each position of a row whose length is not a multiple of a vector's.
#include "io/half_rows.hpp"

#include <Imath/half.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "retina/bit_masks.hpp"

namespace eyestream::io {
namespace {

using retina::bits_of;

TEST(HalfRows, EveryHalfIsImathsFloatBitForBit) {
  const int n = 65536 + 7;
  std::vector<std::uint16_t> red(n), green(n), blue(n);
  for (int i = 0; i < n; ++i) {
    red[size_t(i)] = std::uint16_t(i);
    green[size_t(i)] = std::uint16_t(i * 7 + 3);
    blue[size_t(i)] = std::uint16_t(65535 - i);
  }
  std::vector<float> rgb(3 * size_t(n)), grey(3 * size_t(n));
  halves_to_rgb(red.data(), green.data(), blue.data(), rgb.data(), n);
  halves_to_grey_rgb(red.data(), grey.data(), n);
  const auto imath = [](std::uint16_t h) {
    Imath::half v;
    v.setBits(h);
    return float(v);
  };
  int wrong = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint16_t h[3] = {red[size_t(i)], green[size_t(i)], blue[size_t(i)]};
    for (int c = 0; c < 3; ++c) {
      wrong += bits_of(rgb[3 * size_t(i) + size_t(c)]) != bits_of(imath(h[c]));
      wrong += bits_of(grey[3 * size_t(i) + size_t(c)]) != bits_of(imath(h[0]));
    }
    if (wrong > 0) {
      ADD_FAILURE() << "half 0x" << std::hex << h[0] << " / 0x" << h[1] << " / 0x" << h[2];
      break;
    }
  }
  EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace eyestream::io
