// The mesopic claims of Jacobs et al. 2015 sec. 2.3 (docs/model.md).
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "pipeline/eye/eye_simulator.hpp"
#include "pipeline/eye/mesopic_stage.hpp"
#include "retina/smooth_noise.hpp"
#include "samples/dusk.hpp"
#include "tests/test_support.hpp"

namespace eyestream::pipeline {
namespace {

const cv::Size kFrame(320, 180);

Plan plan_for(const Settings& s, cv::Size frame = kFrame) { return test::plan_for(s, frame.width, frame.height); }

Settings colour_only() {
  Settings s;
  s.acuity_loss = false;
  return s;
}

// The dusk scene's checker and target lit so a perfect white has luminance `white`.
cv::Mat lit(double white) { return samples::dusk_reflectance(kFrame) * white; }

// The stage's rendering at adaptation log A of the scene lit at 10^A / 0.18
// (a viewer adapted to the mid-grey wall).
cv::Mat render(const MesopicStage& stage, const Plan& plan, double a, double t = 0.0) {
  cv::Mat out;
  stage.render(lit(std::pow(10.0, a) / 0.18), retina::ToneCurve(a, plan.tone), a, t, out);
  return out;
}

cv::Vec3f patch_mean(const cv::Mat& img, int patch) {
  const cv::Rect r = samples::dusk_checker_patch(patch, kFrame);
  const cv::Rect inner(r.x + r.width / 4, r.y + r.height / 4, r.width / 2, r.height / 2);
  const cv::Scalar m = cv::mean(img(inner));
  return {float(m[0]), float(m[1]), float(m[2])};
}

// CIE 1976 u'v' chromaticity of linear Rec.709 RGB.
cv::Point2d uv(const cv::Vec3f& rgb) {
  const double x = 0.4124 * rgb[0] + 0.3576 * rgb[1] + 0.1805 * rgb[2];
  const double y = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
  const double z = 0.0193 * rgb[0] + 0.1192 * rgb[1] + 0.9505 * rgb[2];
  const double d = x + 15 * y + 3 * z;
  return {4 * x / d, 9 * y / d};
}

const cv::Point2d kWhite = uv({1, 1, 1});

TEST(Mesopic, PhotopicAdaptationChangesNothing) {
  // Adapted to 10 cd/m^2 and brighter: bit-identical to the same run
  // without the mesopic stage, acuity loss included.
  Settings off;
  off.mesopic = false;
  const Plan on_plan = plan_for(Settings{}), off_plan = plan_for(off);
  const MesopicStage on(on_plan), none(off_plan);
  for (double a : {1.0, 2.0, 4.0})
    for (double t : {0.0, 0.3, 1.7})
      EXPECT_EQ(cv::norm(render(on, on_plan, a, t), render(none, off_plan, a, t), cv::NORM_INF), 0.0) << a;
}

TEST(Mesopic, ChromaFallsAndHueMovesTowardPurpleAsLightFalls) {
  const Plan plan = plan_for(colour_only());
  const MesopicStage stage(plan);
  const cv::Vec3f tint(1.15f, 0.90f, 1.25f);
  const cv::Point2d purple = uv(tint);
  double previous_chroma = 1e9, previous_distance = 1e9, previous_grey = 1e9;
  for (double a = 0.0; a >= -2.001; a -= 0.25) {  // rho from 1 to 0
    const cv::Mat out = render(stage, plan, a);
    double chroma = 0, distance = 0;
    for (int i = 0; i < 24; ++i) {
      const cv::Point2d c = uv(patch_mean(out, i));
      chroma += 13.0 * cv::norm(c - kWhite) / 24;  // CIE 1976 saturation s_uv
      distance += cv::norm(c - purple) / 24;
    }
    const double grey = cv::norm(uv(patch_mean(out, 21)) - purple);  // neutral 5
    EXPECT_LT(chroma, previous_chroma) << "A=" << a;
    EXPECT_LT(distance, previous_distance + 1e-9) << "A=" << a;
    EXPECT_LT(grey, previous_grey + 1e-9) << "A=" << a;
    previous_chroma = chroma, previous_distance = distance, previous_grey = grey;
  }
  EXPECT_LT(previous_distance, 1e-3) << "fully scotopic: every patch is the tint";
}

TEST(Mesopic, BlueGainsOnRedOfEqualPhotopicLuminance) {
  const Plan plan = plan_for(colour_only());
  const MesopicStage stage(plan);
  cv::Mat scene(2, 2, CV_32FC3);
  auto ratio_at = [&](double a) {
    const float l = float(std::pow(10.0, a));
    cv::Mat pair(1, 2, CV_32FC3);
    pair.at<cv::Vec3f>(0, 0) = cv::Vec3f(0, 0, l / 0.0722f);  // blue
    pair.at<cv::Vec3f>(0, 1) = cv::Vec3f(l / 0.2126f, 0, 0);  // red
    cv::Mat out;
    stage.render(pair, retina::ToneCurve(a, plan.tone), a, 0.0, out);
    auto y = [](const cv::Vec3f& p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; };
    return y(out.at<cv::Vec3f>(0, 0)) / y(out.at<cv::Vec3f>(0, 1));
  };
  EXPECT_NEAR(ratio_at(0.5), 1.0, 1e-6) << "photopic: equal";
  double previous = 1.0;
  for (double a : {-0.5, -1.0, -1.5, -2.0}) {
    const double r = ratio_at(a);
    EXPECT_GT(r, previous) << "A=" << a;
    previous = r;
  }
}

// High-frequency energy of the resolution target, relative to its mean.
double detail(const cv::Mat& img) {
  cv::Mat g, lap;
  cv::extractChannel(img(samples::dusk_target(kFrame)), g, 1);
  cv::Laplacian(g, lap, CV_32F);
  const double mean = cv::mean(g)[0];
  return cv::norm(lap) / (mean * std::sqrt(double(lap.total())));
}

TEST(Mesopic, FineDetailFallsWithLuminanceAndFlickersButRepeatsWithTheSeed) {
  Settings sharp;
  sharp.acuity_loss = false;
  const Plan plan = plan_for(Settings{}), sharp_plan = plan_for(sharp);
  const MesopicStage stage(plan), reference(sharp_plan);
  // Detail kept by the acuity loss, relative to the same rendering without
  // it, averaged over a few instants (the loss is stochastic).
  auto kept = [&](double a) {
    double sum = 0;
    for (double t : {0.0, 0.5, 1.0, 1.5})
      sum += detail(render(stage, plan, a, t)) / detail(render(reference, sharp_plan, a, t)) / 4;
    return sum;
  };
  EXPECT_DOUBLE_EQ(kept(1.0), 1.0) << "photopic: all detail";
  // At rho = 1 only sub-pixel bands can go (none visible at this size).
  double previous = kept(0.0);
  EXPECT_LE(previous, 1.0 + 1e-6);
  for (double a : {-0.5, -1.0, -1.5, -2.5, -3.5}) {
    const double k = kept(a);
    EXPECT_LT(k, previous) << "A=" << a;
    previous = k;
  }
  EXPECT_LT(previous, 0.5) << "deep mesopic: most detail gone";
  // Unstable in time at a mesopic level (Jacobs et al. 2015 fig. 12)...
  const cv::Mat t0 = render(stage, plan, -1.0, 0.0), t1 = render(stage, plan, -1.0, 1.0);
  EXPECT_GT(cv::norm(t0, t1, cv::NORM_INF), 0.01);
  // ...yet identical for the same seed, and different for another.
  const MesopicStage again(plan);
  EXPECT_EQ(cv::norm(t0, render(again, plan, -1.0, 0.0), cv::NORM_INF), 0.0);
  Settings other;
  other.seed = 99;
  const Plan other_plan = plan_for(other);
  const MesopicStage reseeded(other_plan);
  EXPECT_GT(cv::norm(t0, render(reseeded, other_plan, -1.0, 0.0), cv::NORM_INF), 0.01);
}

TEST(Mesopic, AcuityWeightsAreSmoothAtTheScaleOfTheNoiseGrid) {
  // The demo's size: 640 px, so the 0.5 deg noise cell is 10.9 px.
  const cv::Size frame(640, 360);
  const Plan plan = plan_for(Settings{}, frame);
  const MesopicStage stage(plan);
  // A uniform scene, so rho is constant and the level's variation is g X.
  const cv::Mat level =
      stage.acuity_level(test::constant_frame(frame.width, frame.height, {0.1f, 0.1f, 0.1f}), -1.0, 0.37);
  double lo, hi;
  cv::minMaxLoc(level, &lo, &hi);
  EXPECT_GT(hi - lo, 0.5) << "the level does vary across the frame";
  // Per-pixel noise X of gain g would change the level between neighbours
  // by g E|X1 - X2| = 0.25 * 1.13 on average; the coarse field by a small
  // fraction of that.
  const cv::Mat dx =
      cv::abs(level(cv::Rect(1, 0, level.cols - 1, level.rows)) - level(cv::Rect(0, 0, level.cols - 1, level.rows)));
  EXPECT_LT(cv::mean(dx)[0], 0.15 * 0.25 * 1.13);
  // The binary weight of a band near the mean level flips between few
  // neighbours (per-pixel noise: about half of them).
  const float tau = 3.5f / 8.0f;
  int flips = 0;
  for (int y = 0; y < level.rows; ++y)
    for (int x = 1; x < level.cols; ++x) flips += (level.at<float>(y, x) > tau) != (level.at<float>(y, x - 1) > tau);
  EXPECT_LT(flips, int(0.05 * level.total()));
}

TEST(Mesopic, SmoothNoiseIsStandardNormalAtEveryPoint) {
  retina::SmoothNoiseParams p;
  p.cell_px = 8;
  p.clip = 100;
  double sum = 0, sum_sq = 0;
  int n = 0;
  for (int k = 0; k < 40; ++k) {
    const cv::Mat x = retina::smooth_noise({64, 64}, 0.37 * k, p, 5, retina::RandomStream::kAcuity);
    sum += cv::sum(x)[0];
    sum_sq += x.dot(x);
    n += int(x.total());
  }
  const double mean = sum / n, sd = std::sqrt(sum_sq / n - mean * mean);
  EXPECT_NEAR(mean, 0.0, 0.1);
  EXPECT_NEAR(sd, 1.0, 0.1);
}

}  // namespace
}  // namespace eyestream::pipeline
