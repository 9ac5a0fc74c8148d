// The split glare engine (glare/split_convolver.hpp) against the exact FFT
// engine: it moves light without adding any, and its retinal image of the
// headlights scene stays within a stated error of the exact one.
#include <gtest/gtest.h>

#include <iostream>

#include "glare/fft_convolver.hpp"
#include "glare/psf_weights.hpp"
#include "glare/pupil.hpp"
#include "glare/split_convolver.hpp"
#include "pipeline/bench/bench_scene.hpp"
#include "retina/luminance.hpp"

namespace eyestream::glare {
namespace {

constexpr int kW = 640, kH = 360;
constexpr double kPpd = kW / 29.3;  // the default viewing condition at 640 px

const FftConvolver& exact() {
  static const ComponentKernels k = build_component_kernels(kW, kH, kPpd);
  static const FftConvolver engine(k);
  return engine;
}

PsfWeights night_weights() { return psf_weights(ViewerProfile{}, -1.0, moon_spencer_pupil_mm(-1.0)); }

// The excess over a 100 cd/m^2 display peak of the headlights scene.
cv::Mat headlight_excess() {
  const pipeline::BenchScene scene = pipeline::load_bench_scene("headlights", kW, kH, 2);
  cv::Mat excess = scene.frames[0].rgb.clone();
  excess.forEach<cv::Vec3f>([](cv::Vec3f& p, const int*) {
    const float l = retina::photopic_luminance(p);
    p = l > 100.0f ? p * ((l - 100.0f) / l) : cv::Vec3f();
  });
  return excess;
}

double total(const cv::Mat& m) { return cv::sum(m).dot(cv::Scalar(1, 1, 1)); }

TEST(SplitEngine, MovesLightWithoutAddingAnyLikeTheExactEngine) {
  for (int factor : {2, 4}) {
    const SplitConvolver split(kW, kH, kPpd, factor);
    cv::Mat point = cv::Mat::zeros(kH, kW, CV_32FC3);
    point.at<cv::Vec3f>(kH / 2, kW / 2) = cv::Vec3f(1e6f, 1e6f, 1e6f);
    const double in = total(point);
    const double by_split = total(split.convolve(point, night_weights()));
    const double by_exact = total(exact().convolve(point, night_weights()));
    EXPECT_LE(by_split, in) << "factor " << factor;
    // Both kernels hold the PSF's energy within the frame's reach; they
    // agree within 0.05 % (measured 0.014 %).
    EXPECT_NEAR(by_split / by_exact, 1.0, 5e-4) << "factor " << factor;
  }
}

TEST(SplitEngine, WithFlareLinesItStillMovesLightWithoutAddingAny) {
  // The tail's lines are the frame-resolution pattern averaged over each
  // reduced pixel (flare_lines.hpp); energy is kept ring by ring.
  const EyeOptics optics({}, PsfModel::vos, true, 0.0, kPpd);
  const FftConvolver lined(build_component_kernels(kW, kH, kPpd, optics));
  cv::Mat point = cv::Mat::zeros(kH, kW, CV_32FC3);
  point.at<cv::Vec3f>(kH / 2, kW / 2) = cv::Vec3f(1e6f, 1e6f, 1e6f);
  const double by_exact = total(lined.convolve(point, night_weights()));
  EXPECT_NEAR(by_exact / total(exact().convolve(point, night_weights())), 1.0, 1e-6) << "lines move light only";
  for (int factor : {2, 4}) {
    const double by_split = total(SplitConvolver(kW, kH, kPpd, factor, optics).convolve(point, night_weights()));
    EXPECT_LE(by_split, total(point));
    EXPECT_NEAR(by_split / by_exact, 1.0, 5e-4) << "factor " << factor;
  }
}

TEST(SplitEngine, DenseAndSparseInputsTakeTheirPathsAndAgree) {
  // A dense image goes through the FFT path; its energy matches the
  // exact engine's as well.
  cv::Mat dense(kH, kW, CV_32FC3);
  cv::randu(dense, 0.0, 1000.0);
  const SplitConvolver split(kW, kH, kPpd, 4);
  EXPECT_NEAR(total(split.convolve(dense, night_weights())) / total(exact().convolve(dense, night_weights())), 1.0,
              5e-4);
}

// Each channel with its own weights gets what it gets when all three
// share them (the glare stage's set-up spreads three components in one
// pass on that), from the exact engine and from the split engine's dense
// and sparse paths.
TEST(SplitEngine, PerChannelWeightsGiveEachChannelWhatSharedWeightsGive) {
  PsfWeights a, b, c;
  a.core = 1.0;
  b.inner = 1.0;
  c.outer = 0.7;
  c.halo = 0.3;
  const ChannelWeights mixed{a, b, c};
  cv::Mat dense(kH, kW, CV_32FC3);
  cv::randu(dense, 0.0, 1000.0);
  cv::Mat sparse = cv::Mat::zeros(kH, kW, CV_32FC3);
  sparse.at<cv::Vec3f>(kH / 2, kW / 3) = cv::Vec3f(1e5f, 2e5f, 3e5f);
  sparse.at<cv::Vec3f>(10, kW - 5) = cv::Vec3f(4e4f, 1e3f, 7e4f);
  const SplitConvolver split(kW, kH, kPpd, 4);
  for (const cv::Mat* in : {&dense, &sparse}) {
    const cv::Mat by_split = split.convolve(*in, mixed), by_exact = exact().convolve(*in, mixed);
    for (int k = 0; k < 3; ++k) {
      const ChannelWeights same = same_in_every_channel(mixed[size_t(k)]);
      cv::Mat want, got;
      cv::extractChannel(split.convolve(*in, same), want, k);
      cv::extractChannel(by_split, got, k);
      EXPECT_EQ(cv::norm(want, got, cv::NORM_INF), 0.0) << "split, channel " << k << (in == &dense ? ", dense" : ", sparse");
      cv::extractChannel(exact().convolve(*in, same), want, k);
      cv::extractChannel(by_exact, got, k);
      EXPECT_EQ(cv::norm(want, got, cv::NORM_INF), 0.0) << "exact, channel " << k << (in == &dense ? ", dense" : ", sparse");
      EXPECT_GT(cv::norm(got, cv::NORM_INF), 0.0);
    }
  }
}

// Stated error on the headlights scene: the spread excess differs from the
// exact engine's by at most 1.5 % of the exact value plus 0.375 cd/m^2
// (middle factor 2) or 3.5 % plus 0.7 cd/m^2 (factor 4) at every pixel, on
// a 640x360 frame. Measured: 84 % and 91 % of these bounds; 113 % and
// 133 % with the middle band unsharpened (split_convolver.cpp), which met
// the bounds of 2026-12-05 (2 % + 0.5, 5 % + 1) with 85 % and 93 %. With
// the tail at 4 times the middle's reduction handing over at 8 f_tail
// pixels instead of 16, the factor-2 error was 2.1 times its 2 % + 0.5
// bound: the tail's hand-over must lie where its blocks are small against
// the PSF's change.
// The largest |split - exact| / (relative exact + absolute) over every
// pixel and channel: at most 1 when the split engine is within the bound.
double worst_against(const cv::Mat& exact_image, const cv::Mat& split, double relative, double absolute) {
  double worst = 0.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c) {
        const double e = exact_image.at<cv::Vec3f>(y, x)[c], s = split.at<cv::Vec3f>(y, x)[c];
        worst = std::max(worst, std::abs(s - e) / (relative * e + absolute));
      }
  return worst;
}

TEST(SplitEngine, HeadlightsRetinalImageWithinItsStatedErrorOfTheExactEngine) {
  const cv::Mat excess = headlight_excess();
  const cv::Mat reference = exact().convolve(excess, night_weights());
  for (const auto& [factor, relative, absolute] : {std::tuple{2, 0.015, 0.375}, std::tuple{4, 0.035, 0.7}}) {
    const cv::Mat split = SplitConvolver(kW, kH, kPpd, factor).convolve(excess, night_weights());
    const double worst = worst_against(reference, split, relative, absolute);
    std::cout << "factor " << factor << ": " << worst << " of the bound\n";
    EXPECT_LE(worst, 1.0) << "factor " << factor;
  }
}

TEST(SplitEngine, AtTheFrameResolutionOf1080pTheTailsRampIsWithinTheSameBound) {
  // At 65.5 px/deg (1080p's default viewing condition, a 640x360 crop) the
  // halo sets where the tail takes over (4.5 deg, 295 px) and its ramp is
  // half that wide (split_convolver.hpp), as in `balanced` at 1080p;
  // at the frame resolution above the ramp's floor of 8 tail blocks rules.
  // The same bound holds: measured 94 % of it, the near field's error
  // (the same with the tail's wider ramp of the sessions before).
  const double ppd = 1920 / 29.3;
  const cv::Mat excess = headlight_excess();
  const PsfWeights w = night_weights();
  const cv::Mat reference = FftConvolver(build_component_kernels(kW, kH, ppd)).convolve(excess, w);
  const cv::Mat split = SplitConvolver(kW, kH, ppd, 2).convolve(excess, w);
  const double worst = worst_against(reference, split, 0.015, 0.375);
  std::cout << "65.5 px/deg, factor 2: " << worst << " of the bound\n";
  EXPECT_LE(worst, 1.0);
}

TEST(SplitEngine, WhereTheTailTakesOverAPointsGlareIsTheExactEngines) {
  // A point near the left edge at 65.5 px/deg: its glare from 4 to 8 deg
  // away, where the tail takes over from the middle level, against the
  // exact engine's, pixel by pixel. Measured: 2.1 % with the tail's ramp
  // from 4.5 to 6.75 deg (split_convolver.hpp), 1.3 % with the ramp to 9
  // deg of the sessions before, 2.9 % with one to 6 deg.
  const double ppd = 1920 / 29.3;
  cv::Mat point = cv::Mat::zeros(kH, kW, CV_32FC3);
  const cv::Point at(20, kH / 2);
  point.at<cv::Vec3f>(at) = cv::Vec3f(1e6f, 1e6f, 1e6f);
  const PsfWeights w = night_weights();
  const cv::Mat e = FftConvolver(build_component_kernels(kW, kH, ppd)).convolve(point, w);
  const cv::Mat s = SplitConvolver(kW, kH, ppd, 2).convolve(point, w);
  double worst = 0.0;
  int pixels = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double r = std::hypot(x - at.x, y - at.y) / ppd;
      if (r < 4.0 || r > 8.0) continue;
      ++pixels;
      for (int c = 0; c < 3; ++c) {
        const double want = e.at<cv::Vec3f>(y, x)[c], got = s.at<cv::Vec3f>(y, x)[c];
        worst = std::max(worst, std::abs(got - want) / want);
      }
    }
  std::cout << "4-8 deg from a point at 65.5 px/deg, factor 2: worst relative difference " << worst << " over "
            << pixels << " pixels\n";
  EXPECT_GT(pixels, 50000);
  EXPECT_LT(worst, 0.025);
}

TEST(SplitEngine, WithFlareLinesTheHeadlightsErrorIsLargerAndStated) {
  // The tail's streaks are drawn at the tail's resolution: wider and
  // fainter than the exact engine's (flare_lines.hpp). Measured: 91 % and
  // 96 % of the bounds; 82 % and 87 % with the middle band unsharpened.
  const EyeOptics optics({}, PsfModel::vos, true, 0.0, kPpd);
  const cv::Mat excess = headlight_excess();
  const cv::Mat reference =
      FftConvolver(build_component_kernels(kW, kH, kPpd, optics)).convolve(excess, night_weights());
  for (const auto& [factor, relative, absolute] : {std::tuple{2, 0.25, 1.0}, std::tuple{4, 0.5, 1.0}}) {
    const cv::Mat split = SplitConvolver(kW, kH, kPpd, factor, optics).convolve(excess, night_weights());
    const double worst = worst_against(reference, split, relative, absolute);
    std::cout << "flare lines, factor " << factor << ": " << worst << " of the bound\n";
    EXPECT_LE(worst, 1.0) << "factor " << factor;
  }
}

// Red over blue in the ring between r0 and r1 degrees around the centre.
double red_over_blue(const cv::Mat& m, double ppd, double r0, double r1) {
  cv::Vec3d sum(0, 0, 0);
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x) {
      const double r = std::hypot(x - m.cols / 2, y - m.rows / 2) / ppd;
      if (r >= r0 && r < r1) sum += cv::Vec3d(m.at<cv::Vec3f>(y, x));
    }
  return sum[0] / sum[2];
}

TEST(SplitEngine, KeepsTheHalosColourOrder) {
  // A white point: the lenticular halo puts blue inside red (rings from 2 to
  // 4.5 deg). The split engine keeps the ring's colour order, red over blue
  // in its outer part (3.5-4.5 deg) against its inner part (2-3 deg), within
  // 3 % of the exact engine's, at 1080p's default 65.5 px/deg (a 640x360
  // crop). With the tail (1/8 resolution) starting inside the ring it was
  // repainted (7.6 % off here at factor 4; bench p99 CIEDE2000 0.39 -> 0.86 on the 1080p
  // night drive).
  const double ppd = 1920 / 29.3;
  cv::Mat point = cv::Mat::zeros(kH, kW, CV_32FC3);
  point.at<cv::Vec3f>(kH / 2, kW / 2) = cv::Vec3f(1e6f, 1e6f, 1e6f);
  const PsfWeights w = psf_weights(ViewerProfile{}, -2.0, 7.0);  // dark-adapted, wide pupil: a strong halo
  const cv::Mat e = FftConvolver(build_component_kernels(kW, kH, ppd)).convolve(point, w);
  const double order = red_over_blue(e, ppd, 3.5, 4.5) / red_over_blue(e, ppd, 2.0, 3.0);
  EXPECT_GT(order, 1.2) << "the exact engine shows the ring's colour order";
  for (int factor : {2, 4}) {
    const cv::Mat s = SplitConvolver(kW, kH, ppd, factor).convolve(point, w);
    const double split_order = red_over_blue(s, ppd, 3.5, 4.5) / red_over_blue(s, ppd, 2.0, 3.0);
    std::cout << "factor " << factor << ": colour order " << split_order << ", exact " << order << "\n";
    EXPECT_NEAR(split_order / order, 1.0, 0.03) << "factor " << factor;
  }
}

TEST(SplitEngine, IdenticalAcrossRunsAndThreadCounts) {
  const cv::Mat excess = headlight_excess();
  const SplitConvolver split(kW, kH, kPpd, 4);
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  const cv::Mat one = split.convolve(excess, night_weights());
  cv::setNumThreads(2);
  const cv::Mat two = split.convolve(excess, night_weights());
  cv::setNumThreads(threads);
  EXPECT_EQ(cv::norm(one, two, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace eyestream::glare
