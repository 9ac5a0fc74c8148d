// The ZIP predictor and reordering undone by vector loops, against the two
// transforms written out a byte at a time here (OpenEXR's definition), on
// random bytes of every length up to 100 and a long odd one.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "io/exr_zip_bytes.hpp"

namespace eyestream::io {
namespace {

std::vector<unsigned char> random_bytes(size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<unsigned char> v(n);
  for (unsigned char& b : v) b = static_cast<unsigned char>(rng());
  return v;
}

TEST(ExrZipBytes, ThePredictorIsUndoneAsAByteAtATime) {
  for (size_t n : {size_t(0), size_t(1), size_t(2), size_t(15), size_t(16), size_t(17), size_t(33), size_t(100),
                   size_t(1) << 20 | 7}) {
    for (size_t m = n; m <= n + (n <= 100 ? 3 : 0); ++m) {
      std::vector<unsigned char> got = random_bytes(m, unsigned(m)), want = got;
      for (size_t i = 1; i < m; ++i) want[i] = static_cast<unsigned char>(int(want[i - 1]) + int(want[i]) - 128);
      undo_zip_predictor(got.data(), m);
      EXPECT_TRUE(got == want) << m << " bytes";
    }
  }
}

TEST(ExrZipBytes, TheReorderingIsUndoneAsAByteAtATime) {
  for (size_t n = 0; n <= 100; ++n) {
    const std::vector<unsigned char> in = random_bytes(n, unsigned(n) + 1000);
    std::vector<unsigned char> want(n), got(n + 1, 0xAB);  // one guard byte
    const unsigned char* t1 = in.data();
    const unsigned char* t2 = in.data() + (n + 1) / 2;
    for (size_t s = 0; s < n;) {
      want[s++] = *t1++;
      if (s < n) want[s++] = *t2++;
    }
    undo_zip_reorder(in.data(), got.data(), n);
    EXPECT_TRUE(std::equal(want.begin(), want.end(), got.begin())) << n << " bytes";
    EXPECT_EQ(got[n], 0xAB) << n << " bytes: nothing written past the end";
  }
}

}  // namespace
}  // namespace eyestream::io
