#include "retina/adaptation.hpp"

#include <gtest/gtest.h>

namespace eyestream::retina {
namespace {

const AdaptationParams kSeed;  // a1 = 0.75, a2 = 0.2 (Jacobs et al. 2015 App. A)

TEST(Adaptation, MovesTowardBrighterAtRateA1) {
  EXPECT_DOUBLE_EQ(adaptation_step(0.0, 3.0, 1.0, kSeed), 0.75);
  EXPECT_DOUBLE_EQ(adaptation_step(0.0, 3.0, 0.5, kSeed), 0.375);
}

TEST(Adaptation, MovesTowardDarkerAtRateA2) {
  EXPECT_DOUBLE_EQ(adaptation_step(0.0, -3.0, 1.0, kSeed), -0.2);
  EXPECT_DOUBLE_EQ(adaptation_step(0.0, -3.0, 2.5, kSeed), -0.5);
}

TEST(Adaptation, NeverOvershootsTheTarget) {
  EXPECT_DOUBLE_EQ(adaptation_step(0.0, 0.1, 1.0, kSeed), 0.1);
  EXPECT_DOUBLE_EQ(adaptation_step(0.0, -0.1, 10.0, kSeed), -0.1);
  EXPECT_DOUBLE_EQ(adaptation_step(2.0, 2.0, 100.0, kSeed), 2.0);
}

TEST(Adaptation, IsAsymmetricDarkAdaptationIsSlower) {
  // Time to move 1.5 log units each way, integrated in 1 ms steps.
  auto seconds_to_reach = [](double from, double to) {
    double a = from;
    int steps = 0;
    while (a != to) {
      a = adaptation_step(a, to, 1e-3, kSeed);
      ++steps;
    }
    return steps * 1e-3;
  };
  EXPECT_NEAR(seconds_to_reach(0.0, 1.5), 2.0, 2e-3);
  EXPECT_NEAR(seconds_to_reach(1.5, 0.0), 7.5, 2e-3);
}

TEST(Adaptation, StepsComposeExactly) {
  // Two steps of dt equal one of 2 dt while the target is not reached.
  const double once = adaptation_step(0.0, 5.0, 2.0, kSeed);
  const double twice = adaptation_step(adaptation_step(0.0, 5.0, 1.0, kSeed), 5.0, 1.0, kSeed);
  EXPECT_DOUBLE_EQ(once, twice);
}

TEST(Adaptation, ZeroAndNegativeDtChangeNothing) {
  EXPECT_DOUBLE_EQ(adaptation_step(1.0, 3.0, 0.0, kSeed), 1.0);
  EXPECT_DOUBLE_EQ(adaptation_step(1.0, 3.0, -1.0, kSeed), 1.0);
}

}  // namespace
}  // namespace eyestream::retina
