// The optics claims of Spencer et al. 1995 and Yoshida et al. 2008 (docs/model.md).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "glare/fft_convolver.hpp"
#include "glare/psf_kernel.hpp"
#include "glare/psf_weights.hpp"
#include "glare/pupil.hpp"
#include "glare/vos_psf.hpp"
#include "pipeline/eye/glare_stage.hpp"
#include "tests/test_support.hpp"

namespace eyestream::glare {
namespace {

constexpr int kW = 160, kH = 90;
constexpr double kPpd = 160 / 29.3;  // the default viewing condition at 160 px

const ComponentKernels& kernels() {
  static const ComponentKernels k = build_component_kernels(kW, kH, kPpd);
  return k;
}

// Share of a component's energy within a circle of radius t (deg).
double energy_within(const std::function<double(double)>& f, double t) {
  return hemisphere_integral([&](double u) { return u <= t ? f(u) : 0.0; });
}

TEST(Glare, EachKernelHoldsThePsfsEnergyWithinItsReach) {
  // A kernel spans (2W - 1) x (2H - 1) pixels: its sum lies between the
  // analytic energy within the inscribed circle and the circumscribed one.
  const ComponentKernels& k = kernels();
  const double inner_r = (kH - 1) / kPpd, outer_r = std::hypot(kW - 1, kH - 1) / kPpd;
  auto check = [&](const cv::Mat& m, const std::function<double(double)>& f, const char* name) {
    const double sum = cv::sum(m)[0];
    EXPECT_GE(sum, energy_within(f, inner_r) * 0.99) << name;
    EXPECT_LE(sum, energy_within(f, outer_r) * 1.01) << name;
  };
  check(k.core, vos_f0, "f0");
  check(k.inner, vos_f1, "f1");
  check(k.outer, vos_f2, "f2");
  check(
      k.halo[1], [](double t) { return vos_f3(t, 550.0); }, "f3");
  EXPECT_NEAR(cv::sum(k.core)[0], 1.0, 1e-3) << "the core is all within reach";
  EXPECT_LT(cv::sum(k.outer)[0], 0.95) << "f2's far tail is beyond a 160x90 frame's reach";
  EXPECT_EQ(k.core.cols, 2 * kW - 1) << "reaches across the whole frame";
  EXPECT_EQ(k.core.rows, 2 * kH - 1);
}

TEST(Glare, WeightsSumToOneAndBlendContinuously) {
  double previous_core = psf_weights(ViewerProfile{}, -4.0, 5.0).core;
  for (double a = -4.0; a <= 2.0; a += 0.01) {
    const PsfWeights w = psf_weights(ViewerProfile{}, a, 5.0);
    EXPECT_NEAR(w.core + w.inner + w.outer + w.halo, 1.0, 1e-12);
    EXPECT_LT(std::abs(w.core - previous_core), 0.002) << "no popping at A=" << a;
    previous_core = w.core;
  }
}

// Spencer et al. 1995: the share of light scattered beyond 0.05 deg rises from about
// 0.36 at age 20 to about 0.45 at age 60.
TEST(Glare, ScatterBeyondFiveHundredthsOfADegreeGrowsWithAge) {
  ViewerProfile young, old;
  young.age_years = 20;
  old.age_years = 60;
  EXPECT_NEAR(energy_beyond(psf_weights(young, 2.0, 2.0), 0.05), 0.36, 0.01);
  EXPECT_NEAR(energy_beyond(psf_weights(old, 2.0, 2.0), 0.05), 0.45, 0.01);
}

TEST(Glare, PupilIsAboutThreeMillimetresAtTenCandelas) {
  EXPECT_NEAR(moon_spencer_pupil_mm(1.0), 3.0, 0.15);
  EXPECT_GT(moon_spencer_pupil_mm(-4.0), 7.0);
  EXPECT_LT(moon_spencer_pupil_mm(5.0), 2.0);
}

// Radial profile of a kernel (mean over rings one pixel wide).
std::vector<double> radial(const cv::Mat& k) {
  const cv::Point c(k.cols / 2, k.rows / 2);
  std::vector<double> sum(size_t(k.rows / 2), 0.0), n(sum.size(), 0.0);
  for (int y = 0; y < k.rows; ++y)
    for (int x = 0; x < k.cols; ++x) {
      const size_t r = size_t(std::lround(std::hypot(x - c.x, y - c.y)));
      if (r < sum.size()) sum[r] += k.at<double>(y, x), n[r] += 1;
    }
  for (size_t r = 0; r < sum.size(); ++r) sum[r] /= std::max(n[r], 1.0);
  return sum;
}

// Spencer et al. 1995: a point source shows a coloured halo ring near 3 deg under
// scotopic adaptation (pupil wide) and none under photopic (pupil narrow).
TEST(Glare, HaloRingNearThreeDegreesOnlyWhenThePupilIsWide) {
  const ComponentKernels& k = kernels();
  auto profile = [&](double a, int c) {
    return radial(combined_kernel(k, psf_weights(ViewerProfile{}, a, moon_spencer_pupil_mm(a)), c));
  };
  const std::vector<double> dark = profile(-3.0, 1), bright = profile(3.0, 1);
  const size_t ring = size_t(std::lround(3.0 * kPpd));
  // A local maximum near 3 deg in the dark...
  size_t peak = 0;
  for (size_t r = size_t(2.0 * kPpd); r < size_t(4.0 * kPpd); ++r)
    if (dark[r] > dark[r - 1] && dark[r] >= dark[r + 1]) peak = r;
  EXPECT_NEAR(double(peak), double(ring), 0.5 * kPpd);
  // ...none in daylight: the profile only falls.
  for (size_t r = 2; r < bright.size(); ++r) EXPECT_LE(bright[r], bright[r - 1] * (1 + 1e-9)) << r;
  // Blue rings sit inside red ones.
  const std::vector<double> red = profile(-3.0, 0), blue = profile(-3.0, 2);
  auto ring_radius = [&](const std::vector<double>& p) {
    double m = 0, w = 0;
    for (size_t r = size_t(1.5 * kPpd); r < size_t(5.0 * kPpd) && r < p.size(); ++r) {
      const double excess = p[r] - bright[r];
      if (excess > 0) m += excess * double(r), w += excess;
    }
    return m / w;
  };
  EXPECT_LT(ring_radius(blue), ring_radius(red));
}

TEST(Glare, FftEngineAddsNoLightAndMovesItAcrossTheFrame) {
  const ComponentKernels& k = kernels();
  const FftConvolver engine(k);
  const PsfWeights w = psf_weights(ViewerProfile{}, -1.0, moon_spencer_pupil_mm(-1.0));
  cv::Mat scene = cv::Mat::zeros(kH, kW, CV_32FC3);
  const cv::Point source(3, kH / 2);  // at the left edge
  scene.at<cv::Vec3f>(source) = cv::Vec3f(1e6f, 1e6f, 1e6f);
  const cv::Mat out = engine.convolve(scene, w);
  for (int c = 0; c < 3; ++c) {
    // What stays in the frame is exactly the kernel's mass over the frame's offsets.
    const cv::Mat kc = combined_kernel(k, w, c);
    const cv::Rect window(k.centre().x - source.x, k.centre().y - source.y, kW, kH);
    const double expected = 1e6 * cv::sum(kc(window))[0];
    double got = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) got += out.at<cv::Vec3f>(y, x)[c];
    EXPECT_NEAR(got / expected, 1.0, 1e-4) << "channel " << c;
    EXPECT_LT(got, 1e6);
  }
  EXPECT_GT(out.at<cv::Vec3f>(kH / 2, kW - 2)[1], 0.0f) << "a light at one edge veils the other";
}

TEST(Glare, KernelsAreIdenticalAcrossBuilds) {
  const ComponentKernels again = build_component_kernels(kW, kH, kPpd);
  EXPECT_EQ(cv::norm(again.outer, kernels().outer, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(again.halo[2], kernels().halo[2], cv::NORM_INF), 0.0);
}

TEST(Glare, OlderViewersSeeMoreVeil) {
  const ComponentKernels& k = kernels();
  const FftConvolver engine(k);
  cv::Mat scene = cv::Mat::zeros(kH, kW, CV_32FC3);
  scene.at<cv::Vec3f>(kH / 2, kW / 2) = cv::Vec3f(1e6f, 1e6f, 1e6f);
  ViewerProfile young, old;
  young.age_years = 25;
  old.age_years = 70;
  const cv::Point at(kW / 2 + int(5 * kPpd), kH / 2);  // 5 deg away
  const float veil_young = engine.convolve(scene, psf_weights(young, 0.0, 3.0)).at<cv::Vec3f>(at)[1];
  const float veil_old = engine.convolve(scene, psf_weights(old, 0.0, 3.0)).at<cv::Vec3f>(at)[1];
  // The ratio the continuous model predicts at 5 deg (Spencer et al. 1995 eqs. 5-10).
  auto psf_at = [](const PsfWeights& w, double t) {
    return w.core * vos_f0(t) + w.inner * vos_f1(t) + w.outer * vos_f2(t) + w.halo * vos_f3(t, 568.0);
  };
  const double expected = psf_at(psf_weights(old, 0.0, 3.0), 5.0) / psf_at(psf_weights(young, 0.0, 3.0), 5.0);
  EXPECT_GT(expected, 1.9);
  EXPECT_NEAR(veil_old / veil_young, expected, 0.05 * expected);
}

}  // namespace
}  // namespace eyestream::glare

namespace eyestream::pipeline {
namespace {

TEST(GlareStage, ExcessModeFramesWithNothingAboveTheDisplayPeakSkipTheWork) {
  Settings s;
  s.glare_mode = "excess";
  GlareStage stage(test::plan_for(s, 64, 36));
  const cv::Mat dim = test::constant_frame(64, 36, {50, 50, 50});
  bool ran = true;
  const cv::Mat out = stage.apply(dim, 1.0, 0.0, 0.0, &ran);
  EXPECT_FALSE(ran);
  EXPECT_EQ(out.data, dim.data) << "the frame itself, untouched";
  cv::Mat bright = dim.clone();
  bright.at<cv::Vec3f>(10, 10) = cv::Vec3f(1e5f, 1e5f, 1e5f);
  const cv::Mat glared = stage.apply(bright, 1.0, 0.0, 0.0, &ran);
  EXPECT_TRUE(ran);
  EXPECT_GT(glared.at<cv::Vec3f>(20, 40)[1], 50.0f) << "a veil on the dim part";
  EXPECT_NEAR(cv::sum(glared)[1], cv::sum(bright)[1], 0.05 * cv::sum(bright)[1]) << "light moved, not made";
  EXPECT_LE(cv::sum(glared)[1], cv::sum(bright)[1] * (1 + 1e-6));
}

TEST(GlareStage, GaussianModelMovesLightWithoutAddingAny) {
  Settings s;
  s.psf_model = "gaussian";
  GlareStage stage(test::plan_for(s, 96, 54));
  EXPECT_TRUE(stage.kernels().core.empty()) << "no Vos kernels built";
  cv::Mat scene = test::constant_frame(96, 54, {1, 1, 1});
  scene.at<cv::Vec3f>(27, 48) = cv::Vec3f(1e5f, 1e5f, 1e5f);
  bool ran = false;
  const cv::Mat out = stage.apply(scene, 0.0, 1.0, 0.0, &ran);
  EXPECT_TRUE(ran);
  // sigma = 0.34 deg is 1.1 px here: light reaches the neighbours, and the
  // total stays (the source is far from the edges; the 1 cd/m^2 surround
  // scatters in what the background scatters out).
  EXPECT_GT(out.at<cv::Vec3f>(27, 49)[1], 1000.0f);
  EXPECT_NEAR(cv::sum(out)[1], cv::sum(scene)[1], 1e-4 * cv::sum(scene)[1]);
}

}  // namespace
}  // namespace eyestream::pipeline
