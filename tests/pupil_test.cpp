// Pupil diameter models (docs/model.md): Moon-Spencer and Watson-Yellott.
#include <gtest/gtest.h>

#include <cmath>

#include "glare/eye_optics.hpp"
#include "glare/pupil.hpp"

namespace eyestream::glare {
namespace {

TEST(Pupil, WatsonYellottGivesItsFormulasValuesWorkedByHand) {
  // Where (F/846)^0.41 = 2, Stanley-Davies gives 7.75 - 5.75 * 2/4 = 4.875
  // mm, and the reference age 28.58 changes nothing.
  const double flux = 846.0 * std::pow(2.0, 1.0 / 0.41);
  EXPECT_NEAR(watson_yellott_pupil_mm(flux / 100.0, 100.0, 28.58), 4.875, 1e-9);
  // At 70: 4.875 + 41.42 (0.02132 - 0.009562 * 4.875) = 3.827 mm.
  EXPECT_NEAR(watson_yellott_pupil_mm(flux / 100.0, 100.0, 70.0), 3.8273, 1e-3);
  // One eye takes a tenth of the flux: the same pupil at ten times the luminance.
  EXPECT_NEAR(watson_yellott_pupil_mm(flux / 10.0, 100.0, 28.58, 1), 4.875, 1e-9);
  // Ages outside 20-83 are held at the formula's ends.
  EXPECT_EQ(watson_yellott_pupil_mm(1.0, 100.0, 95.0), watson_yellott_pupil_mm(1.0, 100.0, 83.0));
  EXPECT_EQ(watson_yellott_pupil_mm(1.0, 100.0, 5.0), watson_yellott_pupil_mm(1.0, 100.0, 20.0));
}

TEST(Pupil, WatsonYellottNarrowsWithLightFieldAndAge) {
  double previous = 100.0;
  for (double log_l = -4.0; log_l <= 4.0; log_l += 0.5) {
    const double d = watson_yellott_pupil_mm(std::pow(10.0, log_l), 1000.0, 30.0);
    EXPECT_LT(d, previous);
    EXPECT_GT(d, 1.5);
    EXPECT_LT(d, 8.0);
    previous = d;
  }
  EXPECT_LT(watson_yellott_pupil_mm(10.0, 2000.0, 30.0), watson_yellott_pupil_mm(10.0, 200.0, 30.0));
  EXPECT_LT(watson_yellott_pupil_mm(0.01, 1000.0, 75.0), watson_yellott_pupil_mm(0.01, 1000.0, 25.0));
}

TEST(Pupil, TheViewersModelAndFieldAreUsed) {
  ViewerProfile viewer;
  EXPECT_NEAR(pupil_mm(viewer, 1.0, 500.0), 3.0, 0.15) << "Moon-Spencer: about 3 mm at 10 cd/m^2";
  viewer.pupil = PupilModel::watson_yellott;
  EXPECT_EQ(pupil_mm(viewer, 1.0, 500.0), watson_yellott_pupil_mm(10.0, 500.0, viewer.age_years))
      << "no field named: the frame's";
  viewer.pupil_field_deg = 20.0;
  EXPECT_EQ(pupil_mm(viewer, 1.0, 500.0), watson_yellott_pupil_mm(10.0, M_PI * 100.0, viewer.age_years));
  EXPECT_EQ(EyeOptics(viewer, PsfModel::vos, false, 500.0).pupil_mm(1.0), pupil_mm(viewer, 1.0, 500.0));
}

}  // namespace
}  // namespace eyestream::glare
