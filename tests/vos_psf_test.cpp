#include "glare/vos_psf.hpp"

#include <gtest/gtest.h>

namespace eyestream::glare {
namespace {

// docs/model.md: each Vos component is a unit-volume density over the hemisphere.
TEST(VosPsf, EachComponentIntegratesToOneOverTheHemisphere) {
  EXPECT_NEAR(hemisphere_integral(vos_f0), 1.0, 0.01);
  EXPECT_NEAR(hemisphere_integral(vos_f1), 1.0, 0.01);
  EXPECT_NEAR(hemisphere_integral(vos_f2), 1.0, 0.01);
  for (double lambda : {400.0, 568.0, 700.0})
    EXPECT_NEAR(hemisphere_integral([lambda](double t) { return vos_f3(t, lambda); }), 1.0, 0.01) << lambda;
}

TEST(VosPsf, HaloRingPeaksNearThreeDegreesAt568nm) {
  EXPECT_GT(vos_f3(3.0, 568.0), vos_f3(2.5, 568.0));
  EXPECT_GT(vos_f3(3.0, 568.0), vos_f3(3.5, 568.0));
}

}  // namespace
}  // namespace eyestream::glare
