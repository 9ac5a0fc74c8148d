// Haze and age in the PSF weights and the flare lines: haze moves its share
// of the core into the bloom and thins the lines (Matsuda and Ikedo); no
// age or haze makes a weight negative or weakens the corona.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "glare/eye_optics.hpp"
#include "glare/flare_lines.hpp"
#include "glare/psf_kernel.hpp"
#include "glare/psf_weights.hpp"

namespace eyestream::glare {
namespace {

PsfWeights weights_for(double age, double haze, double adaptation_log = 2.0) {
  ViewerProfile v;
  v.age_years = age;
  v.haze = haze;
  return psf_weights(v, adaptation_log, 3.0);
}

TEST(Haze, MovesItsShareOfTheCoreIntoTheBloom) {
  for (double age : {25.0, 70.0})
    for (double haze : {0.1, 0.3, 0.5}) {
      const PsfWeights clear = weights_for(age, 0.0), hazy = weights_for(age, haze);
      EXPECT_NEAR(hazy.core, (1.0 - haze) * clear.core, 1e-12) << "age " << age << ", haze " << haze;
      EXPECT_NEAR(hazy.outer - clear.outer, haze * clear.core, 1e-12);
      EXPECT_DOUBLE_EQ(hazy.inner, clear.inner) << "the corona keeps its weight";
    }
}

TEST(Haze, WeightsStayValidAtEveryAgeAndHazeAndTheCoronaKeepsItsShare) {
  for (double age : {20.0, 60.0, 85.0, 90.0, 100.0})
    for (double haze : {0.0, 0.3, 0.5})
      for (double a : {-4.0, -1.0, 2.0}) {
        const PsfWeights w = weights_for(age, haze, a);
        EXPECT_GT(w.core, 0.0) << "age " << age << ", haze " << haze;
        EXPECT_GE(w.outer, 0.0);
        EXPECT_NEAR(w.core + w.inner + w.outer + w.halo, 1.0, 1e-12);
        EXPECT_DOUBLE_EQ(w.inner, 0.478) << "age " << age << ", haze " << haze << ": f1 is never renormalised";
      }
  // Below the clamp the age term is Spencer et al. 1995's eq. 10 to the letter.
  EXPECT_NEAR(weights_for(60, 0).core, 0.384 - 6.9e-9 * std::pow(60.0, 4.0), 1e-12);
}

// Local maxima on the ring of radius r (pixels) above `factor` times its mean.
int visible_streaks(const cv::Mat& k, double r, double factor) {
  const int cx = k.cols / 2, cy = k.rows / 2, n = 720;
  std::vector<double> v(n);
  double mean = 0;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    v[size_t(i)] = k.at<double>(int(std::lround(cy + r * std::sin(a))), int(std::lround(cx + r * std::cos(a))));
    mean += v[size_t(i)] / n;
  }
  int count = 0;
  for (int i = 0; i < n; ++i) {
    const double here = v[size_t(i)], prev = v[size_t((i + n - 1) % n)], next = v[size_t((i + 1) % n)];
    if (here > factor * mean && here >= prev && here > next) ++count;
  }
  return count;
}

TEST(Haze, ThinsTheFlareLines) {
  constexpr int kW = 200, kH = 120;
  constexpr double kPpd = 20.0;
  ViewerProfile clear, hazy;
  hazy.haze = 0.3;
  const ComponentKernels a = build_component_kernels(kW, kH, kPpd, EyeOptics(clear, PsfModel::vos, true));
  const ComponentKernels b = build_component_kernels(kW, kH, kPpd, EyeOptics(hazy, PsfModel::vos, true));
  const int seen_clear = visible_streaks(a.inner, 2.0 * kPpd, 1.5), seen_hazy = visible_streaks(b.inner, 2.0 * kPpd, 1.5);
  EXPECT_GT(seen_clear, 10);
  EXPECT_LT(seen_hazy, 0.8 * seen_clear) << "streaks at 2 deg: clear " << seen_clear << ", haze 0.3 " << seen_hazy;
  EXPECT_GT(flare_lines(clear, FlareKind::corona).lines.size(), flare_lines(hazy, FlareKind::corona).lines.size());
}

}  // namespace
}  // namespace eyestream::glare
