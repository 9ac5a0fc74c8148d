// The cie PSF model: CIE 146:2002's general disability glare equation
// (docs/model.md) as the scattered part of the kernel.
#include <gtest/gtest.h>

#include <cmath>

#include "glare/cie_glare.hpp"
#include "glare/eye_optics.hpp"
#include "glare/fft_convolver.hpp"
#include "glare/psf_kernel.hpp"
#include "glare/veiling_luminance.hpp"
#include "glare/vos_psf.hpp"

namespace eyestream::glare {
namespace {

constexpr int kW = 256, kH = 32;
constexpr double kPpd = 10.0;  // 25.6 deg across: a source 10 deg from a point fits

TEST(CieGlare, TheEquationGivesItsPublishedValues) {
  // 10/t^3 + (5/t^2 + 0.1 p/t)(1 + (A/62.5)^4) + 0.0025 p at p = 0.5,
  // worked by hand.
  const double expected[2][3] = {{15.18053, 0.9584915, 0.0676580}, {22.99752, 1.844245, 0.1527936}};
  const double ages[2] = {25, 70}, angles[3] = {1, 3, 10};
  for (int a = 0; a < 2; ++a)
    for (int t = 0; t < 3; ++t)
      EXPECT_NEAR(cie_general_glare(angles[t], ages[a], 0.5), expected[a][t], 1e-6 * expected[a][t])
          << "age " << ages[a] << ", " << angles[t] << " deg";
}

TEST(CieGlare, KernelVeilAtOneThreeAndTenDegreesMatchesTheEquationForAges25And70) {
  for (double age : {25.0, 70.0}) {
    ViewerProfile viewer;
    viewer.age_years = age;
    const EyeOptics optics(viewer, PsfModel::cie);
    const ComponentKernels k = build_component_kernels(kW, kH, kPpd, optics);
    const PsfWeights w = optics.weights(2.0);  // photopic: no halo
    EXPECT_EQ(w.halo, 0.0);
    // A one-pixel source of luminance L is an illuminance E = L * pixel_sr at the eye.
    cv::Mat luminance = cv::Mat::zeros(kH, kW, CV_32F);
    const cv::Point source(20, kH / 2);
    const double l = 1e6, pixel_sr = std::pow(M_PI / 180.0 / kPpd, 2.0);
    luminance.at<float>(source) = float(l);
    for (double t : {1.0, 3.0, 10.0}) {
      const double veil = veiling_luminance(luminance, k, w, source.x + t * kPpd, source.y, 0.0);
      const double expected = l * pixel_sr * cie_general_glare(t, age, viewer.pigmentation);
      EXPECT_NEAR(veil / expected, 1.0, 0.02) << "age " << age << ", " << t << " deg";
    }
  }
}

TEST(CieGlare, ScatteredShareGrowsWithAgeAndPigmentation) {
  const double young = cie_scatter(25, 0.5).scattered_share, old = cie_scatter(70, 0.5).scattered_share;
  EXPECT_GT(young, 0.2);
  EXPECT_LT(young, 0.4);
  EXPECT_GT(old, young * 1.2);
  EXPECT_LT(old, 1.0);
  EXPECT_GT(cie_scatter(25, 1.2).scattered_share, cie_scatter(25, 0.0).scattered_share);
  // Unit volume once scaled (hemisphere_integral as for the Vos components).
  const CieScatter s = cie_scatter(70, 1.0);
  EXPECT_NEAR(hemisphere_integral([&](double t) { return s.density(t); }), 1.0, 1e-9);
}

TEST(CieGlare, PigmentationMattersFarOutAndTheWeightsSumToOne) {
  // p enters through the eye wall: negligible at 1 deg, large at 60 deg.
  const double near_ratio = cie_general_glare(1, 25, 1.2) / cie_general_glare(1, 25, 0.0);
  const double far_ratio = cie_general_glare(60, 25, 1.2) / cie_general_glare(60, 25, 0.0);
  EXPECT_LT(near_ratio, 1.01);
  EXPECT_GT(far_ratio, 2.0);
  ViewerProfile viewer;
  viewer.age_years = 90;
  viewer.haze = 0.5;
  for (double a : {-4.0, -1.0, 2.0}) {
    const PsfWeights w = EyeOptics(viewer, PsfModel::cie).weights(a);
    EXPECT_NEAR(w.core + w.inner + w.outer + w.halo, 1.0, 1e-12);
    EXPECT_GE(w.core, 0.0);
  }
}

TEST(CieGlare, TheFftEngineConservesTheKernelsEnergy) {
  ViewerProfile viewer;
  viewer.age_years = 70;
  const EyeOptics optics(viewer, PsfModel::cie);
  const ComponentKernels k = build_component_kernels(kW, kH, kPpd, optics);
  const PsfWeights w = optics.weights(-2.5);  // scotopic: the halo is on
  EXPECT_GT(w.halo, 0.0);
  cv::Mat scene = cv::Mat::zeros(kH, kW, CV_32FC3);
  const cv::Point source(kW / 2, kH / 2);
  scene.at<cv::Vec3f>(source) = cv::Vec3f(1e6f, 1e6f, 1e6f);
  const cv::Mat out = FftConvolver(k).convolve(scene, w);
  for (int c = 0; c < 3; ++c) {
    const cv::Rect window(k.centre().x - source.x, k.centre().y - source.y, kW, kH);
    const double expected = 1e6 * cv::sum(combined_kernel(k, w, c)(window))[0];
    EXPECT_NEAR(cv::sum(out)[c] / expected, 1.0, 1e-4) << "channel " << c;
  }
}

}  // namespace
}  // namespace eyestream::glare
