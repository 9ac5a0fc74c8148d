// Full-image glare, the default: the whole retinal image goes through the
// PSF, the surround scatters in, and the result does not depend on the
// preview display's peak.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "pipeline/eye/glare_stage.hpp"
#include "retina/luminance.hpp"
#include "tests/test_support.hpp"

namespace eyestream::pipeline {
namespace {

constexpr int kW = 160, kH = 90;

Settings full_glare(const std::string& engine, const std::string& model) {
  Settings s;
  s.glare_engine = engine;
  s.psf_model = model;
  s.skip = false;
  return s;
}

double worst_relative(const cv::Mat& out, double expected) {
  double lo, hi;
  cv::minMaxLoc(out.reshape(1), &lo, &hi);
  return std::max(hi / expected - 1.0, 1.0 - lo / expected);
}

// A uniform 100 cd/m^2 field with a 100 cd/m^2 surround reaches the retina
// as a uniform 100 cd/m^2 field: light scattered out of the frame is
// replaced by light scattered in from the surround.
TEST(FullGlare, AUniformFieldAndSurroundStayUniformToTheCorners) {
  const cv::Mat field = test::constant_frame(kW, kH, {100, 100, 100});
  for (const char* engine : {"exact", "split"})
    for (const char* model : {"vos", "cie", "gaussian"}) {
      GlareStage stage(test::plan_for(full_glare(engine, model), kW, kH));
      const cv::Mat retinal = stage.apply(field, 2.0, 100.0);
      EXPECT_LT(worst_relative(retinal, 100.0), 0.005) << engine << ", " << model;
      // A dark surround: the edges lose what scatters out, the centre less.
      const cv::Mat dark = stage.apply(field, 2.0, 0.0);
      EXPECT_LT(dark.at<cv::Vec3f>(0, 0)[1], dark.at<cv::Vec3f>(kH / 2, kW / 2)[1]) << engine << ", " << model;
    }
}

// The same on an odd-sized frame seen at 54 px/deg (3 deg wide) with the
// convolution at half that (the glare frame halved: the surround's light
// added at half size and brought back with the kept light in one pass),
// rectilinear and equidistant (whose full-resolution plane is the frame
// itself), on one thread as on two.
TEST(FullGlare, AUniformFieldStaysUniformOnAHalvedGlareFrameOfOddSize) {
  constexpr int kOddW = 161, kOddH = 91;
  const cv::Mat field = test::constant_frame(kOddW, kOddH, {100, 100, 100});
  for (const char* projection : {"rectilinear", "equidistant"})
    for (const double resolution : {0.5, 1.0})
      for (const char* engine : {"exact", "split"})
        for (const char* model : {"vos", "gaussian"}) {
          Settings s = full_glare(engine, model);
          s.geometry.fov_deg = 3.0;
          s.geometry.projection = projection;
          s.glare_resolution = resolution;
          const std::string what = std::string(projection) + ", " + std::to_string(resolution) + ", " + engine + ", " + model;
          GlareStage stage(test::plan_for(s, kOddW, kOddH));
          const cv::Mat retinal = stage.apply(field, 2.0, 100.0);
          EXPECT_LT(worst_relative(retinal, 100.0), 0.005) << what;
          const int threads = cv::getNumThreads();
          cv::setNumThreads(1);
          const cv::Mat one = stage.apply(field, 2.0, 100.0);
          cv::setNumThreads(threads);
          EXPECT_EQ(cv::norm(retinal, one, cv::NORM_INF), 0.0) << what << ": one thread";
          // A dark surround: the edges lose what scatters out, the centre less.
          const cv::Mat dark = stage.apply(field, 2.0, 0.0);
          EXPECT_LT(dark.at<cv::Vec3f>(0, 0)[1], dark.at<cv::Vec3f>(kOddH / 2, kOddW / 2)[1]) << what;
        }
}

// Skipping: a neutral uniform field equal to its surround comes back as it
// is; a coloured one does not (the grey surround scatters into its edges).
TEST(FullGlare, OnlyANeutralUniformFieldEqualToItsSurroundIsSkipped) {
  Settings s;
  GlareStage stage(test::plan_for(s, kW, kH));
  bool ran = true;
  const cv::Mat grey = test::constant_frame(kW, kH, {50, 50, 50});
  const cv::Mat same = stage.apply(grey, 1.0, 50.0, 3.0, &ran);
  EXPECT_FALSE(ran);
  EXPECT_EQ(same.data, grey.data);
  const cv::Mat red = test::constant_frame(kW, kH, {200, 0, 0});
  const cv::Mat glared = stage.apply(red, 1.0, 0.2126 * 200, 3.0, &ran);
  EXPECT_TRUE(ran);
  EXPECT_GT(glared.at<cv::Vec3f>(0, 0)[1], 1.0f) << "green scattered in from the grey surround at the corner";
}

// A lamp of 90 cd/m^2 (below the 100 cd/m^2 display peak) veils its
// surroundings, and the display peak changes nothing.
TEST(FullGlare, ByDefaultEveryLampVeilsWhateverTheDisplayPeak) {
  cv::Mat scene = test::constant_frame(kW, kH, {0.1f, 0.1f, 0.1f});
  cv::circle(scene, {40, 45}, 2, cv::Scalar::all(90.0), cv::FILLED);
  Settings s;  // the defaults
  GlareStage stage(test::plan_for(s, kW, kH));
  const cv::Mat retinal = stage.apply(scene, -1.0, 0.1);
  const double ppd = test::plan_for(s, kW, kH).pixels_per_degree;
  const int two_deg = 40 + int(std::lround(2 * ppd));
  EXPECT_GT(retinal.at<cv::Vec3f>(45, two_deg)[1], 0.1f * 1.05f) << "a veil 2 deg from the lamp";
  s.display_peak_cd_m2 = 1000.0;
  GlareStage other(test::plan_for(s, kW, kH));
  EXPECT_EQ(cv::norm(retinal, other.apply(scene, -1.0, 0.1), cv::NORM_INF), 0.0) << "the display peak does not matter";
}

// The picture and the report agree: on a dark frame lit by one lamp, the
// retinal luminance 3 deg away is the veil the report computes there.
TEST(FullGlare, ThePictureShowsTheVeilTheReportMeasures) {
  cv::Mat scene = test::constant_frame(kW, kH, {0, 0, 0});
  cv::circle(scene, {40, 45}, 1, cv::Scalar::all(5000.0), cv::FILLED);
  Settings s = full_glare("exact", "vos");
  s.report = "r.csv";
  s.flare_lines = false;
  const Plan plan = test::plan_for(s, kW, kH);
  GlareStage stage(plan);
  const cv::Mat retinal = stage.apply(scene, 0.0, 0.0, 3.0);
  cv::Mat luminance(scene.size(), CV_32F);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) luminance.at<float>(y, x) = retina::photopic_luminance(scene.at<cv::Vec3f>(y, x));
  const int x = 40 + int(std::lround(3 * plan.pixels_per_degree));
  const std::optional<double> veil = stage.veil_at(luminance, 0.0, 3.0, x + 0.5, 45.5, 1.0);
  ASSERT_TRUE(veil.has_value());
  const double shown = retina::photopic_luminance(retinal.at<cv::Vec3f>(45, x));
  EXPECT_NEAR(shown / *veil, 1.0, 0.03) << "picture " << shown << " cd/m^2, report " << *veil;
}

}  // namespace
}  // namespace eyestream::pipeline
