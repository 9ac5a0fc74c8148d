// CIEDE2000 against the published test pairs of Sharma, Wu and Dalal
// (2005), Table 1, and CIELAB of the display primaries.
#include <gtest/gtest.h>

#include "retina/colour_difference.hpp"

namespace eyestream::retina {
namespace {

struct Pair {
  cv::Vec3d a, b;
  double de;
};

TEST(ColourDifference, Ciede2000MatchesSharmasTestPairs) {
  const Pair pairs[] = {
      {{50.0000, 2.6772, -79.7751}, {50.0000, 0.0000, -82.7485}, 2.0425},
      {{50.0000, 3.1571, -77.2803}, {50.0000, 0.0000, -82.7485}, 2.8615},
      {{50.0000, 2.8361, -74.0200}, {50.0000, 0.0000, -82.7485}, 3.4412},
      {{50.0000, -1.3802, -84.2814}, {50.0000, 0.0000, -82.7485}, 1.0000},
      {{50.0000, 0.0000, 0.0000}, {50.0000, -1.0000, 2.0000}, 2.3669},
      {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0009}, 7.1792},
      {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
      {{2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082},
  };
  for (const Pair& p : pairs) {
    EXPECT_NEAR(ciede2000(p.a, p.b), p.de, 1e-4) << p.a << " " << p.b;
    EXPECT_NEAR(ciede2000(p.b, p.a), p.de, 1e-4) << "symmetric";
  }
  EXPECT_EQ(ciede2000({40, 10, -5}, {40, 10, -5}), 0.0);
}

TEST(ColourDifference, LabOfWhiteBlackAndGrey) {
  const cv::Vec3d white = lab_from_linear_rec709({1, 1, 1});
  EXPECT_NEAR(white[0], 100.0, 1e-3);
  EXPECT_NEAR(white[1], 0.0, 1e-2);
  EXPECT_NEAR(white[2], 0.0, 1e-2);
  EXPECT_NEAR(lab_from_linear_rec709({0, 0, 0})[0], 0.0, 1e-9);
  EXPECT_NEAR(lab_from_linear_rec709({0.18f, 0.18f, 0.18f})[0], 49.5, 0.1) << "18 % grey is L* about 50";
}

}  // namespace
}  // namespace eyestream::retina
