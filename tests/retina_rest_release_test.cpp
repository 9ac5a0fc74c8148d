// The retina stage lets go of the state's equilibrium B_inf and response
// R (two grid images) once the frame's afterimages are drawn
// (retina_stage.hpp): they are not held between frames, and a checkpoint
// made then still carries them, recomputed from the last stimulus. Checked
// against Jacobs et al. 2015 eqs. 6 and 1 written out here.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "pipeline/eye/eye_simulator.hpp"
#include "pipeline/settings/quality_presets.hpp"
#include "retina/tone_curve.hpp"
#include "tests/test_support.hpp"

namespace eyestream::pipeline {
namespace {

TEST(RetinaRestRelease, TheEquilibriumIsNotHeldBetweenFramesAndACheckpointCarriesIt) {
  constexpr int kW = 96, kH = 54;
  for (const char* preset : {"reference", "balanced", "fast"}) {
    Settings s;
    apply_quality_preset(preset, s);
    const Plan plan = test::plan_for(s, kW, kH, 30.0);
    EyeSimulator eye(plan);
    cv::Mat scene = test::constant_frame(kW, kH, {0.5f, 0.5f, 0.5f});
    cv::rectangle(scene, cv::Rect(30, 20, 12, 10), cv::Scalar(4000, 3000, 800), cv::FILLED);
    for (int i = 0; i < 6; ++i) {
      const double t0 = i / 30.0, t1 = (i + 1) / 30.0;
      eye.process({scene, t0, i, "test"}, {{t0, t1, 30.0 + 4 * i, 27.0, false}});
      EXPECT_FALSE(eye.retina().state().holds_rest()) << preset << ", frame " << i;
    }
    bool started = false;
    const std::vector<cv::Mat> mats = eye.retina().save(started);  // B, D, B_inf, R, stimulus, bookkeeping
    ASSERT_TRUE(started);
    ASSERT_EQ(mats.size(), 6u);
    ASSERT_FALSE(mats[2].empty()) << preset;
    cv::Mat b_inf, response, stimulus;
    mats[2].convertTo(b_inf, CV_64FC3);
    mats[3].convertTo(response, CV_64FC3);
    mats[4].convertTo(stimulus, CV_64FC3);
    const retina::PhotoreceptorParams& p = plan.retina.receptors;
    const retina::ToneCurve curve(mats[5].at<double>(0), plan.tone);
    double worst_b = 0.0, worst_r = 0.0;
    for (int y = 0; y < stimulus.rows; ++y)
      for (int x = 0; x < stimulus.cols; ++x)
        for (int c = 0; c < 3; ++c) {
          const double i = std::max(stimulus.at<cv::Vec3d>(y, x)[c], 0.0);
          const double b = p.bleach_rate[c] * i / (p.bleach_rate[c] * i + p.regen_rate_per_s[c]);  // eq. 6
          const double n = plan.tone.exponent, sigma = curve.sigma();
          const double r = i > 0.0 ? std::pow(i, n) / (std::pow(i, n) + std::pow(sigma, n)) : 0.0;  // eq. 1
          worst_b = std::max(worst_b, std::abs(b_inf.at<cv::Vec3d>(y, x)[c] - b));
          worst_r = std::max(worst_r, std::abs(response.at<cv::Vec3d>(y, x)[c] - r));
        }
    EXPECT_LT(worst_b, 1e-6) << preset;
    EXPECT_LT(worst_r, 1e-5) << preset;
  }
}

TEST(RetinaRestRelease, RecalledRestIsTheStepsOwnBytes) {
  // What a step leaves (B_inf and R of its stimulus) against rest_for()
  // of the same stimulus and curve, after the state has moved: the same
  // bytes, in float and in double, so a checkpoint made after the release
  // holds what the uninterrupted run held.
  for (const bool precise : {false, true}) {
    const retina::PhotoreceptorParams params;
    retina::RetinaState state(cv::Size(37, 23), params, precise);
    const int type = precise ? CV_64FC3 : CV_32FC3;
    cv::Mat lms(23, 37, type);
    cv::randu(lms, 0.0, 5000.0);
    lms(cv::Rect(0, 0, 37, 5)).setTo(cv::Scalar::all(0.2));  // a uniform run, as off the frame
    const retina::ToneCurve curve(0.3, retina::ToneCurveParams{});
    state.rest(lms * 0.1, curve);
    state.step(lms, curve, 1.0 / 30.0);
    ASSERT_TRUE(state.holds_rest());
    const std::vector<cv::Mat> held = state.save();
    const retina::RestOfStimulus recalled = state.rest_for(lms, curve);
    EXPECT_EQ(cv::norm(held[2], recalled.bleached, cv::NORM_INF), 0.0) << (precise ? "double" : "float");
    EXPECT_EQ(cv::norm(held[3], recalled.response, cv::NORM_INF), 0.0) << (precise ? "double" : "float");
    state.release_rest();
    EXPECT_FALSE(state.holds_rest());
    EXPECT_TRUE(state.save()[2].empty());
  }
}

}  // namespace
}  // namespace eyestream::pipeline
