// The upper eyelid and its lashes in the wave-optics aperture
// (--eyelid-mrd1, glare/wave_aperture.hpp): the lid darkens the aperture
// above its margin's shadow, which a light above the gaze lowers by the
// margin's depth times the tangent of the light's angle (computed here
// from the geometry, not read from the code); an open eye's lid leaves a
// small pupil exactly as it was; a squinting lid adds the vertical streak
// its horizontal edge diffracts; and the command line refuses the lid
// without the wave model.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "glare/wave_aperture.hpp"
#include "glare/wave_pattern.hpp"
#include "tests/test_support.hpp"

namespace eyestream::glare {
namespace {

constexpr double kPpd = 21.8;

// The aperture's rows as true millimetres (y down) for pupil_mm.
double row_mm(const WaveAperture& a, int row, double pupil_mm) {
  const double dx = a.side_mm / a.samples, x0 = -0.5 * a.side_mm + 0.5 * dx;
  return (x0 + row * dx) / (0.5 * a.side_mm / pupil_mm);
}

double row_power(const cv::Mat& field, int row) {
  double sum = 0.0;
  for (int c = 0; c < field.cols; ++c) {
    const cv::Vec2d v = field.at<cv::Vec2d>(row, c);
    sum += v[0] * v[0] + v[1] * v[1];
  }
  return sum;
}

TEST(Eyelid, TheLidDarkensTheApertureAboveItsShadowWhichALightAboveLowers) {
  constexpr double kMrd1 = 2.0, kPupil = 6.0;
  const WaveAperture open = viewer_aperture(3), lidded = viewer_aperture(3, kMrd1);
  for (const double light_deg : {0.0, -10.0, 8.0}) {  // (negative: above the gaze)
    const WaveState s{kPupil, 0.0, 0.0, light_deg};
    const cv::Mat without = aperture_field(open, s), with = aperture_field(lidded, s);
    // The margin 3.5 mm in front of the pupil, seen along the light.
    const double shadow = -kMrd1 - 3.5 * std::tan(light_deg * M_PI / 180.0);
    const double sample_mm = row_mm(open, 1, kPupil) - row_mm(open, 0, kPupil);
    int dark_rows = 0, lit_rows_above = 0, open_rows_below = 0;
    for (int r = 0; r < with.rows; ++r) {
      const double y = row_mm(open, r, kPupil);
      if (row_power(without, r) == 0.0) continue;  // outside the pupil
      if (y < shadow - sample_mm) {
        ++dark_rows;
        lit_rows_above += row_power(with, r) > 0.0;
      }
      // Just below the shadow the lashes' roots block their share (4 per
      // mm, 0.07-0.12 mm thick: about 40 %), not the whole row.
      if (y > shadow + sample_mm && y < shadow + 0.2) {
        EXPECT_GT(row_power(with, r), 0.3 * row_power(without, r)) << light_deg << " deg, " << y << " mm";
        ++open_rows_below;
      }
      // Below the lashes' reach (they sag at most tan(25 deg)^2 / (4 curl),
      // 1.22 mm, plus half their width, and 13 mm of depth times the
      // light's tangent further) the lid changes nothing.
      const double lashes = 1.3 + 13.0 * std::max(0.0, -std::tan(light_deg * M_PI / 180.0));
      if (y > -kMrd1 + lashes + sample_mm && y > shadow + sample_mm) {
        ASSERT_EQ(row_power(with, r), row_power(without, r)) << light_deg << " deg, " << y << " mm";
      }
    }
    EXPECT_GT(dark_rows, light_deg > 0.0 ? 5 : 20) << light_deg << " deg";
    EXPECT_EQ(lit_rows_above, 0) << light_deg << " deg: the lid above its shadow";
    EXPECT_GT(open_rows_below, 5) << light_deg << " deg";
    // The lashes: dark samples below the margin's shadow, more for a light above.
    if (light_deg == -10.0) {
      int lash_samples = 0;
      for (int r = 0; r < with.rows; ++r)
        if (row_mm(open, r, kPupil) > shadow + sample_mm)
          for (int c = 0; c < with.cols; ++c)
            lash_samples += without.at<cv::Vec2d>(r, c) != cv::Vec2d(0, 0) && with.at<cv::Vec2d>(r, c) == cv::Vec2d(0, 0);
      EXPECT_GT(lash_samples, 100) << "lashes cross the opening below the lid";
    }
  }
}

TEST(Eyelid, AnOpenEyesLidLeavesASmallPupilAlone) {
  // The margin 4.5 mm up, the lashes sagging at most 1.3 mm: a 3 mm
  // pupil under a straight-ahead light never meets them.
  const WaveState s{3.0, 0.5, 0.0, 0.0};
  const WavePattern open = wave_pattern(viewer_aperture(3), s, kPpd, 70);
  const WavePattern lidded = wave_pattern(viewer_aperture(3, 4.5), s, kPpd, 70);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(cv::norm(open.rgb[c], lidded.rgb[c], cv::NORM_INF), 0.0);
}

// The modulation's energy (G) in the 0.5-3 deg rings within 10 deg of the
// vertical and of the horizontal over that within 10 deg of the diagonals.
double axes_over_diagonals(const WavePattern& p) {
  double axes = 0.0, diagonals = 0.0;
  for (int y = -p.radius; y <= p.radius; ++y)
    for (int x = -p.radius; x <= p.radius; ++x) {
      const double t = std::hypot(x, y) / p.pixels_per_degree;
      if (t < 0.5 || t > 3.0) continue;
      const double angle = std::atan2(std::abs(double(y)), std::abs(double(x))) * 180.0 / M_PI;
      const double m = p.rgb[1].at<double>(y + p.radius, x + p.radius) - 1.0;
      if (angle > 80.0 || angle < 10.0) axes += m * m;
      if (std::abs(angle - 45.0) < 10.0) diagonals += m * m;
    }
  return axes / diagonals;
}

TEST(Eyelid, ASquintingLidAndItsLashesStreakAlongTheAxes) {
  // The lid's horizontal edge streaks vertically, the hanging lashes
  // horizontally: the modulation gathers along the axes.
  const WaveState s{6.0, 0.5, 0.0, 0.0};
  for (const std::int64_t seed : {3, 11, 1, 2, 5}) {
    const double open = axes_over_diagonals(wave_pattern(viewer_aperture(seed), s, kPpd, 70));
    const double squint = axes_over_diagonals(wave_pattern(viewer_aperture(seed, 1.5), s, kPpd, 70));
    std::printf("seed %lld: modulation along the axes over the diagonals, open %.2f, squinting (MRD1 1.5 mm) %.2f\n",
                static_cast<long long>(seed), open, squint);
    EXPECT_GT(squint, 1.3 * open) << "seed " << seed;
  }
}

TEST(Eyelid, TheCommandLineRefusesALidWithoutTheWaveModel) {
  test::ScratchDir dir;
  const auto r = test::run_eyestream("psf -o " + (dir / "k.exr") + " --eyelid-mrd1 2");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("eyestream: error: --eyelid-mrd1"), std::string::npos) << r.output;
  const auto ok = test::run_eyestream("psf -o " + (dir / "k.exr") + " --eyelid-mrd1 2 --flare-model wave");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

}  // namespace
}  // namespace eyestream::glare
