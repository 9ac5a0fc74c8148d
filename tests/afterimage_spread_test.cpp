// Soft afterimages spread as sigma^2 = 0.01 deg^2/s x t (Jacobs et al. 2015
// sec. 2.4) whatever the frame rate, the resolution and the preset: 2 s
// after a flash the added blur is 0.141 deg.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "pipeline/eye/eye_simulator.hpp"
#include "pipeline/settings/quality_presets.hpp"
#include "retina/diffusion.hpp"
#include "tests/test_support.hpp"

namespace eyestream::pipeline {
namespace {

// Variance (in samples^2) along x of a profile given by the column sums of `m`.
double column_variance(const cv::Mat& m) {
  cv::Mat sums;
  cv::reduce(m, sums, 0, cv::REDUCE_SUM, CV_64F);
  double total = 0, mean = 0, second = 0;
  for (int x = 0; x < sums.cols; ++x) total += sums.at<double>(0, x);
  for (int x = 0; x < sums.cols; ++x) mean += x * sums.at<double>(0, x) / total;
  for (int x = 0; x < sums.cols; ++x) second += (x - mean) * (x - mean) * sums.at<double>(0, x) / total;
  return second;
}

TEST(Diffusion, TheFusedDepartureBlurIsTheBlurOfTheDepartureClamped) {
  // Against the composition written out here with diffuse(): one pass
  // (0.36 sites^2, balanced at 30 frames/s), three (1.4, reference) and a
  // Gaussian (6), in float and double, with values that the clamp cuts.
  for (int type : {CV_32FC3, CV_64FC3})
    for (double variance : {0.36, 1.4, 6.0}) {
      cv::Mat state(23, 31, type), rest(23, 31, type);
      cv::randu(state, -0.2, 1.2);
      cv::randu(rest, 0.0, 0.5);
      const double scale = 1.7, hi = 1.0;
      cv::Mat want = state - rest * scale;
      retina::diffuse(want, variance);
      want = rest * scale + want;
      cv::max(want, 0.0, want);
      cv::min(want, hi, want);
      cv::Mat got = state.clone();
      retina::diffuse_departure(got, rest, scale, variance, hi);
      EXPECT_LT(cv::norm(got, want, cv::NORM_INF), type == CV_32FC3 ? 1e-6 : 1e-12) << variance;
    }
}

TEST(Diffusion, TheOnePassInPlaceIsTheSameWhateverTheShapeAndThreads) {
  // One pass writes the state in place by stripes of rows (each sweeping
  // the rows beyond it first): against the composition with diffuse() on
  // grids of one row, one column, fewer rows than stripes and many, and the
  // same bytes on 1, 2 and 3 threads.
  const int threads_before = cv::getNumThreads();
  for (const cv::Size size : {cv::Size(1, 1), cv::Size(7, 1), cv::Size(1, 9), cv::Size(5, 2), cv::Size(3, 64),
                              cv::Size(40, 500)}) {
    cv::Mat state(size, CV_32FC3), rest(size, CV_32FC3);
    cv::randu(state, -0.2, 1.2);
    cv::randu(rest, 0.0, 0.5);
    cv::Mat want = state - rest * 1.7;
    retina::diffuse(want, 0.36);
    want = rest * 1.7 + want;
    cv::max(want, 0.0, want);
    cv::min(want, 1.0, want);
    cv::Mat first;
    for (int threads : {1, 2, 3}) {
      cv::setNumThreads(threads);
      cv::Mat got = state.clone();
      retina::diffuse_departure(got, rest, 1.7, 0.36, 1.0);
      EXPECT_LT(cv::norm(got, want, cv::NORM_INF), 1e-6) << size << ", " << threads << " threads";
      if (first.empty()) first = got;
      EXPECT_EQ(cv::norm(got, first, cv::NORM_INF), 0.0) << size << ", " << threads << " threads";
    }
  }
  cv::setNumThreads(threads_before);
}

TEST(Diffusion, AnAbsurdVarianceIsAUniformBlurNotAnError) {
  cv::Mat m(9, 11, CV_32F, cv::Scalar(0));
  m.at<float>(4, 5) = 99.0f;
  retina::diffuse(m, 1e300);
  double lo, hi;
  cv::minMaxLoc(m, &lo, &hi);
  EXPECT_TRUE(cv::checkRange(m)) << "finite";
  EXPECT_LT(hi - lo, 0.1 * 99.0) << "nearly uniform";
}

TEST(Diffusion, VariancesAddExactlyHoweverTheTimeIsSplit) {
  cv::Mat line(9, 101, CV_64F, cv::Scalar(0));
  line.col(50).setTo(1.0);
  for (double total : {0.02, 0.3, 2.0, 9.0})
    for (int steps : {1, 7, 60}) {
      cv::Mat m = line.clone();
      for (int i = 0; i < steps; ++i) retina::diffuse(m, total / steps);
      EXPECT_NEAR(column_variance(m), total, 2e-3 * total + 1e-9) << total << " sites^2 in " << steps << " steps";
    }
}

// The L-cone bleaching profile of a 1-pixel vertical line flashed for one
// frame: its variance on the retinal grid 2 s after the flash less just
// after it, returned as the added blur sigma (deg).
double added_blur_deg(double ppd, double fps, const std::string& preset) {
  Settings s;
  apply_quality_preset(preset, s);
  s.glare = false;  // the line's own width, not the eye's PSF
  s.surround_cd_m2 = 0.01;
  const int w = int(std::lround(3.0 * ppd)), h = 24;
  s.geometry.fov_deg = w / ppd;
  EyeSimulator eye(test::plan_for(s, w, h, fps));
  const double sites_per_deg = ppd * eye.retina().grid().sites_per_pixel();
  cv::Mat flash = test::constant_frame(w, h, {0.01f, 0.01f, 0.01f});
  flash.col(w / 2).setTo(cv::Scalar::all(1e7));
  const cv::Mat dark = test::constant_frame(w, h, {0.01f, 0.01f, 0.01f});
  double before = 0;
  // Dark (the retina starts at rest), the flash, then dark: measured after
  // the first dark frame and 2 s later.
  const int first = 2, last = first + int(std::lround(2.0 * fps));
  for (int i = 0; i <= last; ++i) {
    const double t0 = i / fps, t1 = (i + 1) / fps;
    eye.process({i == 1 ? flash : dark, t0, i, "test"}, {{t0, t1, w / 2.0, h / 2.0, false}});
    if (i < first) continue;
    bool started = false;
    const std::vector<cv::Mat> state = eye.retina().save(started);  // B, D, B_inf, R, ...
    cv::Mat b[3];
    cv::split(state[0] - state[2], b);  // the departure from equilibrium
    if (i == first) before = column_variance(b[0]);
    if (i == last) return std::sqrt(std::max(column_variance(b[0]) - before, 0.0)) / sites_per_deg;
  }
  return 0;
}

TEST(AfterimageSpread, TwoSecondsAfterAFlashTheBlurIsTheModelsAtEveryRateResolutionAndPreset) {
  const double expected = std::sqrt(0.01 * 2.0);  // 0.141 deg
  for (const char* preset : {"reference", "balanced", "fast"})
    for (double ppd : {20.0, 40.0, 80.0})
      for (double fps : {24.0, 60.0, 120.0}) {
        if (test::kSanitized && (ppd != 20.0 || fps != 24.0)) continue;  // 441 s for all 27 under ASan
        const double blur = added_blur_deg(ppd, fps, preset);
        EXPECT_NEAR(blur / expected, 1.0, 0.10) << preset << ", " << ppd << " px/deg, " << fps << " fps: " << blur
                                                << " deg";
      }
}

}  // namespace
}  // namespace eyestream::pipeline
