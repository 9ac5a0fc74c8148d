// retina/bilinear_rows.hpp's widening of a reduced row against its
// definition computed here one pixel at a time (row[lo] (1 - w) + row[hi] w
// with the axis's taps), bit for bit, for one and three channels: at the
// whole factors whose taps repeat (2, 4, 8: read a block at a time), at
// factors that do not, and on an axis whose repetition is broken part way.
#include "retina/bilinear_rows.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "retina/bilinear_axis.hpp"
#include "retina/bit_masks.hpp"

namespace eyestream::retina {
namespace {

std::vector<float> random_row(int pixels, int channels, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  std::vector<float> row(size_t(pixels) * size_t(channels));
  for (float& v : row) v = std::exp2(u(rng) * 10.0f) * (u(rng) < 0.0f ? -1.0f : 1.0f);
  if (row.size() > 2) row[1] = -0.0f, row[2] = 0.0f;
  return row;
}

// The taps' definition: each pixel and channel from the axis's two taps.
std::vector<float> by_definition(const std::vector<float>& row, const BilinearAxis& a, int channels, int n) {
  std::vector<float> out(size_t(n) * size_t(channels));
  for (int x = 0; x < n; ++x) {
    const float w = a.w[size_t(x)];
    for (int c = 0; c < channels; ++c) {
      const volatile float lo = row[size_t(a.lo[size_t(x)] * channels + c)] * (1.0f - w);
      const volatile float hi = row[size_t(a.hi[size_t(x)] * channels + c)] * w;
      out[size_t(x * channels + c)] = lo + hi;
    }
  }
  return out;
}

// Row and output held between guards: the row's read as NaN if touched, the
// output's checked untouched, as are its values from n on.
constexpr size_t kGuard = 16;

void expect_definition(const BilinearAxis& a, int reduced, int n, const std::string& what) {
  for (int channels : {1, 3}) {
    const std::vector<float> values = random_row(reduced, channels, unsigned(n * 7 + reduced));
    std::vector<float> row(values.size() + 2 * kGuard, std::nanf(""));
    std::copy(values.begin(), values.end(), row.begin() + kGuard);
    std::vector<float> out(a.lo.size() * size_t(channels) + 2 * kGuard, -1.0f);
    (channels == 1 ? enlarge_row : enlarge_row3)(row.data() + kGuard, a, out.data() + kGuard, n);
    const std::vector<float> expected = by_definition(values, a, channels, n);
    for (size_t i = 0; i < out.size(); ++i) {
      const bool written = i >= kGuard && i - kGuard < expected.size();
      ASSERT_EQ(bits_of(out[i]), bits_of(written ? expected[i - kGuard] : -1.0f))
          << what << ", " << channels << " channels, value " << long(i) - long(kGuard) << " of " << n * channels;
    }
    // Exactly sized row and output: a read or write past either (a vector
    // of four floats from a row's last pixel) is the sanitizer build's error.
    const std::vector<float> exact_row(values);
    std::vector<float> exact_out(expected.size());
    (channels == 1 ? enlarge_row : enlarge_row3)(exact_row.data(), a, exact_out.data(), n);
    for (size_t i = 0; i < expected.size(); ++i)
      ASSERT_EQ(bits_of(exact_out[i]), bits_of(expected[i])) << what << ", exactly sized, value " << i;
  }
}

TEST(BilinearRows, WideningIsTheTapsDefinitionBitForBit) {
  for (const auto& [full, reduced] :
       {std::pair{1920, 960}, std::pair{1920, 480}, std::pair{1920, 240}, std::pair{1080, 135}, std::pair{1280, 640},
        std::pair{161, 81}, std::pair{333, 100}, std::pair{1920, 599}, std::pair{8, 8}, std::pair{7, 1},
        std::pair{5, 3}, std::pair{2, 1}}) {
    const BilinearAxis a(full, reduced, float(reduced) / float(full));
    const std::string what = std::to_string(reduced) + " to " + std::to_string(full);
    expect_definition(a, reduced, full, what);
    expect_definition(a, reduced, full / 2, what + ", the first half");
  }
}

// As the acuity loss reads its levels: a scale of 1 / f whatever the sizes,
// so that a map of odd size stops the stretch short of a clamped tail.
TEST(BilinearRows, AWholeScaleOnSizesItDoesNotDivideIsTheDefinitionAtEveryLength) {
  for (const auto& [full, reduced, f] :
       {std::tuple{1925, 241, 8}, std::tuple{1925, 240, 8}, std::tuple{1081, 541, 2}, std::tuple{8, 4, 2},
        std::tuple{16, 2, 8}, std::tuple{64, 17, 4}, std::tuple{64, 32, 2}, std::tuple{64, 8, 8}}) {
    const BilinearAxis a(full, reduced, 1.0f / float(f));
    const std::string what = std::to_string(reduced) + " to " + std::to_string(full) + " at 1/" + std::to_string(f);
    if (full <= 64)
      for (int n = 0; n <= full; ++n) expect_definition(a, reduced, n, what + ", " + std::to_string(n) + " pixels");
    else
      expect_definition(a, reduced, full, what);
  }
  EXPECT_EQ(BilinearAxis(8, 4, 0.5f).repeating.blocks, 2);  // the second reads the map's last pixel
  EXPECT_EQ(BilinearAxis(16, 2, 0.125f).repeating.blocks, 0);
  EXPECT_GT(BilinearAxis(1925, 241, 0.125f).repeating.blocks, 230);
}

TEST(BilinearRows, WholeFactorsRepeatOverAllButTheirBordersAndOthersNeedNot) {
  for (int f : {2, 4, 8}) {
    const BilinearAxis a(1920, 1920 / f, 1.0f / float(f));
    EXPECT_EQ(a.repeating.factor, f);
    // The first 3 f / 2 pixels read map pixel 0 first (those before f / 2
    // clamped to it); the stretch starts at the next, and its last block
    // reads the map's last two pixels.
    EXPECT_EQ(a.repeating.first, 3 * f / 2);
    EXPECT_EQ(a.repeating.blocks, 1920 / f - 2) << f;
    EXPECT_EQ(a.repeating.lo + a.repeating.blocks, 1920 / f - 1) << f;
  }
  EXPECT_EQ(BilinearAxis(333, 100, 100.0f / 333.0f).repeating.blocks, 0);
  EXPECT_EQ(BilinearAxis(8, 8, 1.0f).repeating.factor, 0);
}

TEST(BilinearRows, ABrokenRepetitionEndsTheBlocksAndTheTapsReadTheRest) {
  BilinearAxis a(1920, 480, 0.25f);
  a.w[1001] = 0.3f;  // one pixel's weight, as no repeating axis has it
  a.hi[1500] = a.lo[1500];
  a.repeating = repeating_taps(a.lo, a.hi, a.w);
  EXPECT_EQ(a.repeating.factor, 4);
  EXPECT_EQ(a.repeating.first + 4 * a.repeating.blocks, 998);  // the block holding pixel 1001 is left out
  expect_definition(a, 480, 1920, "a broken axis");
}

}  // namespace
}  // namespace eyestream::retina
