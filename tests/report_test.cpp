// The disability-glare report (driving-simulator previews).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "glare/veiling_luminance.hpp"
#include "glare/vos_psf.hpp"
#include "pipeline/report/report_writer.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

constexpr int kW = 400, kH = 120;
constexpr double kPpd = 400 / 29.3;

const glare::ComponentKernels& kernels() {
  static const glare::ComponentKernels k = glare::build_component_kernels(kW, kH, kPpd);
  return k;
}

double psf_per_sr(const glare::PsfWeights& w, double t) {
  return w.core * glare::vos_f0(t) + w.inner * glare::vos_f1(t) + w.outer * glare::vos_f2(t) +
         w.halo * glare::vos_f3(t, 568.0);
}

// A single small source at t degrees: the report's veil equals E P(t), with
// E the source's illuminance at the eye (luminance times solid angle) and P
// the PSF model's own density per steradian, within 5 %.
TEST(Report, VeilOfASmallSourceMatchesThePsfEquation) {
  const glare::PsfWeights w = glare::psf_weights(glare::ViewerProfile{}, 2.0, 2.5);  // photopic, no halo
  const double pixel_sr = std::pow(M_PI / 180.0 / kPpd, 2);
  for (double t : {2.0, 5.0, 10.0}) {
    cv::Mat luminance = cv::Mat::zeros(kH, kW, CV_32F);
    const int sx = 20, sy = kH / 2;
    luminance.at<float>(sy, sx) = 1e6f;
    const double gaze_x = sx + 0.5 + t * kPpd, gaze_y = sy + 0.5;
    const double veil = glare::veiling_luminance(luminance, kernels(), w, gaze_x, gaze_y, 1.0 * kPpd);
    const double expected = 1e6 * pixel_sr * psf_per_sr(w, t);
    EXPECT_NEAR(veil / expected, 1.0, 0.05) << t << " deg";
  }
}

TEST(Report, ThresholdIncrementFollowsItsFormula) {
  EXPECT_DOUBLE_EQ(glare::threshold_increment(1.0, 1.0), 65.0);
  EXPECT_NEAR(glare::threshold_increment(0.3, 2.0), 65.0 * 0.3 / std::pow(2.0, 0.8), 1e-12);
  EXPECT_TRUE(glare::threshold_increment_valid(1.0));
  EXPECT_FALSE(glare::threshold_increment_valid(20.0));
  EXPECT_FALSE(glare::threshold_increment_valid(0.01));
}

TEST(Report, OlderViewersVeilExceedsTheYoungersByTheModelsRatio) {
  glare::ViewerProfile young, old;
  young.age_years = 25;
  old.age_years = 70;
  cv::Mat luminance = cv::Mat::zeros(kH, kW, CV_32F);
  luminance.at<float>(kH / 2, 20) = 1e6f;
  const double t = 5.0, x = 20.5 + t * kPpd, y = kH / 2 + 0.5;
  const glare::PsfWeights wy = glare::psf_weights(young, 0.0, 3.0), wo = glare::psf_weights(old, 0.0, 3.0);
  const double ratio = glare::veiling_luminance(luminance, kernels(), wo, x, y, kPpd) /
                       glare::veiling_luminance(luminance, kernels(), wy, x, y, kPpd);
  const double predicted = psf_per_sr(wo, t) / psf_per_sr(wy, t);
  EXPECT_GT(predicted, 1.5);
  EXPECT_NEAR(ratio, predicted, 0.05 * predicted);
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Writes the headlights sample (160x90) to DIR/h and runs it with `options`.
void run_headlights(const test::ScratchDir& dir, double duration_s, const std::string& options) {
  if (!std::filesystem::exists(dir / "h")) {
    ASSERT_EQ(test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 160 --height 90 --duration " +
                                  std::to_string(duration_s))
                  .exit_code,
              0);
  }
  const auto r =
      test::run_eyestream("run -i " + (dir / "h/frames") + " -g " + (dir / "h/gaze.csv") + " " + options);
  ASSERT_EQ(r.exit_code, 0) << r.output;
}

TEST(Report, OneDocumentedRowPerFrameAndASummary) {
  test::ScratchDir dir;
  for (const std::string age : {"25", "75"})
    run_headlights(dir, 0.5, "-o " + (dir / (age + ".mp4")) + " --viewer-age " + age + " --report " +
                                 (dir / ("r" + age + ".csv")));
  const std::vector<std::string> rows = lines_of(dir / "r25.csv");
  ASSERT_EQ(rows.size(), 16u) << "a header and one row per frame (15 frames)";
  EXPECT_EQ(rows[0], pipeline::kReportColumns);
  EXPECT_EQ(rows[1].substr(0, 11), "0,0,age 25,");
  std::ifstream json_in(dir / "r25.json");
  const nlohmann::json summary = nlohmann::json::parse(json_in);
  EXPECT_EQ(summary["frames"], 15);
  std::ifstream old_in(dir / "r75.json");
  const nlohmann::json old = nlohmann::json::parse(old_in);
  EXPECT_GT(old["viewers"][0]["veil_cd_m2"]["max"].get<double>(),
            summary["viewers"][0]["veil_cd_m2"]["max"].get<double>());
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "r25.png")) << "charts beside the report";
}

// Splits a CSV row into fields (empty fields kept).
std::vector<std::string> fields(const std::string& row) {
  std::vector<std::string> out;
  std::stringstream in(row);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  if (!row.empty() && row.back() == ',') out.push_back("");
  return out;
}

// The headlights scene's pedestrian (0.6 cd/m^2 on a 0.3 cd/m^2 road) has
// contrast 1; the veil at the target lowers it to (L_t - L_b) / (L_b + L_v),
// more for the older viewer. Two viewers give two rows per frame.
TEST(Report, TargetContrastWithAndWithoutTheVeilPerViewer) {
  test::ScratchDir dir;
  run_headlights(dir, 0.2, "-o " + (dir / "out/%05d.png") + " --viewers 25,75 --report " + (dir / "r.csv") +
                               " --target-mask " + (dir / "h/target"));
  const std::vector<std::string> rows = lines_of(dir / "r.csv");
  ASSERT_EQ(rows.size(), 1u + 2u * 6u) << "a row per frame and viewer";
  const std::vector<std::string> header = fields(rows[0]);
  auto col = [&](const char* name) { return std::find(header.begin(), header.end(), name) - header.begin(); };
  double veiled[2] = {0, 0};
  for (int v = 0; v < 2; ++v) {
    const std::vector<std::string> f = fields(rows[1 + v]);
    ASSERT_EQ(f.size(), header.size());
    EXPECT_EQ(f[col("viewer")], v == 0 ? "age 25" : "age 75");
    const double lt = std::stod(f[col("target_cd_m2")]), lb = std::stod(f[col("background_cd_m2")]);
    const double lv = std::stod(f[col("target_veil_cd_m2")]);
    EXPECT_NEAR(lt, 0.6, 0.6 * 1e-3);
    EXPECT_NEAR(lb, 0.3, 0.3 * 1e-3);
    EXPECT_NEAR(std::stod(f[col("contrast")]), 1.0, 2e-3);
    EXPECT_GT(lv, 0.0);
    veiled[v] = std::stod(f[col("contrast_veiled")]);
    EXPECT_NEAR(veiled[v], (lt - lb) / (lb + lv), 1e-4);
  }
  EXPECT_LT(veiled[1], veiled[0]) << "the older eye's veil hides the pedestrian more";
  std::ifstream json_in(dir / "r.json");
  const nlohmann::json summary = nlohmann::json::parse(json_in);
  ASSERT_EQ(summary["viewers"].size(), 2u);
  EXPECT_EQ(summary["viewers"][1]["frames_with_target"], 6);
}

}  // namespace
}  // namespace eyestream
