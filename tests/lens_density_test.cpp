// The lens's yellowing with age (glare/lens_density.hpp) against Pokorny,
// Smith and Lutze 1987 (Table I and eq. 1, written out here), and its
// effect on what an older viewer is shown.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "glare/lens_density.hpp"
#include "io/exr_file.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

// Table I at four wavelengths: {nm, TL1, TL2}.
struct Row {
  double nm, tl1, tl2;
};
constexpr Row kTable[] = {{400, 0.600, 1.000}, {450, 0.295, 0.005}, {500, 0.167, 0.0}, {550, 0.093, 0.0}};

TEST(LensDensity, IsPokornyEtAl1987AtFourWavelengthsForTwoAges) {
  for (const Row& r : kTable) {
    // Eq. 1: up to 60 years TL1 (1 + 0.02 (A - 32)) + TL2; beyond,
    // TL1 (1.56 + 0.0667 (A - 60)) + TL2.
    EXPECT_NEAR(glare::lens_density(r.nm, 25.0), r.tl1 * (1 + 0.02 * (25 - 32)) + r.tl2, 1e-12) << r.nm;
    EXPECT_NEAR(glare::lens_density(r.nm, 70.0), r.tl1 * (1.56 + 0.0667 * (70 - 60)) + r.tl2, 1e-12) << r.nm;
  }
  // Between the table's rows, and beyond its ends.
  EXPECT_NEAR(glare::lens_density(405, 32.0), 0.5 * (0.600 + 1.000) + 0.5 * (0.510 + 0.583), 1e-12);
  EXPECT_EQ(glare::lens_density(700, 80.0), 0.0);
  EXPECT_EQ(glare::lens_density(380, 40.0), glare::lens_density(400, 40.0));
  EXPECT_EQ(glare::lens_density(450, 5.0), glare::lens_density(450, 20.0)) << "the model starts at 20";
}

TEST(LensDensity, TheFilterIsTheIdentityAt32AndTakesBlueFirstWithAge) {
  const cv::Matx33f at32 = glare::lens_filter_rgb(32.0);
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(at32(k, c), k == c ? 1.0 : 0.0, 1e-6);
  const cv::Matx33f at70 = glare::lens_filter_rgb(70.0);
  const cv::Vec3f red = at70 * cv::Vec3f(1, 0, 0), blue = at70 * cv::Vec3f(0, 0, 1), grey = at70 * cv::Vec3f(1, 1, 1);
  EXPECT_GT(red[0], 0.9f);
  // The blue channel's light lies mostly between 440 and 500 nm, where
  // the 70-year-old's lens transmits 10^-(D(70) - D(32)) = 0.40 to 0.62 of
  // the standard observer's: it keeps a share between those, the red
  // channel nearly all.
  const double t440 = std::pow(10.0, -(glare::lens_density(440, 70) - glare::lens_density(440, 32)));
  const double t500 = std::pow(10.0, -(glare::lens_density(500, 70) - glare::lens_density(500, 32)));
  EXPECT_GT(blue[2], t440);
  EXPECT_LT(blue[2], t500);
  EXPECT_LT(grey[2], grey[1]);
  EXPECT_LT(grey[1], grey[0] + 1e-3f) << "white turns yellow";
  // A younger lens than the standard observer's passes more blue.
  EXPECT_GT((glare::lens_filter_rgb(20.0) * cv::Vec3f(0, 0, 1))[2], 1.0f);
}

// Through the command line: a 70-year-old viewer with --lens-yellowing is
// shown the blue and grey of the adaptation scene with less blue against
// green than without, at two sizes and two frame rates; the plan says so.
TEST(LensDensity, AnOlderViewerIsShownLessBlue) {
  test::ScratchDir dir;
  const struct {
    const char* w;
    const char* h;
    const char* fps;
  } cases[] = {{"96", "54", "30"}, {"160", "90", "60"}};
  for (const auto& c : cases) {
    const std::string scene = dir / (std::string(c.w) + "s");
    ASSERT_EQ(test::run_eyestream("sample adaptation -o " + scene + " --width " + c.w + " --height " + c.h +
                                  " --fps " + c.fps + " --duration 0.1")
                  .exit_code,
              0);
    double blue_over_green[2];
    for (int yellowed = 0; yellowed < 2; ++yellowed) {
      const std::string out = dir / (std::string(c.w) + (yellowed ? "y" : "n"));
      const auto r = test::run_eyestream("run -i " + scene + "/frames -g " + scene + "/gaze.csv -o " + out +
                                         "/%05d.exr --viewer-age 70 --quality fast" +
                                         (yellowed ? " --lens-yellowing" : ""));
      ASSERT_EQ(r.exit_code, 0) << r.output;
      const cv::Scalar mean = cv::mean(io::read_exr(out + "/00002.exr", 1 << 22).rgb);
      blue_over_green[yellowed] = mean[2] / mean[1];
    }
    const double kept = blue_over_green[1] / blue_over_green[0];
    EXPECT_LT(kept, 0.9) << c.w << "x" << c.h << " at " << c.fps << " fps";
    EXPECT_GT(kept, 0.3) << c.w << "x" << c.h << " at " << c.fps << " fps";
    std::cout << c.w << "x" << c.h << " at " << c.fps << " fps: blue against green kept " << kept << "\n";
  }
  const auto plan = test::run_eyestream("run -i " + dir / "96s/frames" + " -o " + dir / "p.mp4" +
                                        " --viewer-age 70 --lens-yellowing --print-plan");
  EXPECT_NE(plan.output.find("lens = yellowed for 70 years"), std::string::npos) << plan.output;
}

}  // namespace
}  // namespace eyestream
