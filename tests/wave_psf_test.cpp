// The wave-optics PSF (glare/wave_pattern.hpp): its lines follow the pupil
// and the light's direction, repeat exactly for the same state, and leave
// the macroscopic PSF's radial energy as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "glare/eye_optics.hpp"
#include "glare/psf_kernel.hpp"
#include "glare/wave_aperture.hpp"
#include "glare/wave_lines.hpp"
#include "glare/wave_pattern.hpp"

namespace eyestream::glare {
namespace {

constexpr double kPpd = 21.8;  // the default viewing condition at 640 px

TEST(WavePsf, LinesFollowThePupilAndTheLightAndRepeatForTheSameState) {
  const WaveAperture aperture = viewer_aperture(7);
  const WaveState base{4.0, 1.0, 0.0, 0.0};
  const WavePattern a = wave_pattern(aperture, base, kPpd, 200);
  const WavePattern same = wave_pattern(aperture, base, kPpd, 200);
  EXPECT_EQ(cv::norm(a.rgb[1], same.rgb[1], cv::NORM_INF), 0.0) << "the same seed and state";
  WaveState pupil = base;
  pupil.pupil_mm = 3.5;
  WaveState moved = base;
  moved.light_x_deg = 4.0;
  const double by_pupil = pattern_correlation(a, wave_pattern(aperture, pupil, kPpd, 200), 0.3, 3.5);
  const double by_light = pattern_correlation(a, wave_pattern(aperture, moved, kPpd, 200), 0.3, 3.5);
  WaveState later = base;
  later.time_s = 1.0 + 1.0 / 30.0;
  const double by_frame = pattern_correlation(a, wave_pattern(aperture, later, kPpd, 200), 0.3, 3.5);
  std::printf("correlation: pupil 4.0 to 3.5 mm %.3f, light moved 4 deg %.3f, one frame later %.3f\n", by_pupil,
              by_light, by_frame);
  EXPECT_LT(by_pupil, 0.7);
  EXPECT_LT(by_light, 0.7);
  EXPECT_GT(by_frame, 0.9) << "particles drift slowly: no popping from frame to frame";
  double lo, hi;
  cv::minMaxLoc(a.rgb[1], &lo, &hi);
  std::printf("modulation range %.3f to %.3f\n", lo, hi);
}

// Energy within t of the kernel's centre (pixel centres), channel c.
double within(const cv::Mat& k, double ppd, double t_deg) {
  double sum = 0.0;
  const int cx = k.cols / 2, cy = k.rows / 2;
  for (int y = 0; y < k.rows; ++y)
    for (int x = 0; x < k.cols; ++x)
      if (std::hypot(x - cx, y - cy) / ppd <= t_deg) sum += k.at<double>(y, x);
  return sum;
}

// The wave lines leave the macroscopic PSF's radial energy (Vos's, with the
// weights of a dark-adapted 70-year-old and of a 25-year-old in daylight)
// as it was at 1, 2, 5 and 10 deg, and haze thins them by its share.
TEST(WavePsf, RadialEnergyIsTheMacroscopicModelsAndHazeThinsTheLines) {
  for (const double age : {25.0, 70.0}) {
    ViewerProfile viewer;
    viewer.age_years = age;
    const EyeOptics optics(viewer);
    const ComponentKernels k = build_component_kernels(480, 480, kPpd, optics);
    const PsfWeights w = optics.weights(age > 50 ? -3.0 : 2.0);
    const WavePattern p = wave_pattern(viewer_aperture(viewer.seed), {optics.pupil_mm(age > 50 ? -3.0 : 2.0)}, kPpd,
                                       int(kWavePatternReach_deg * kPpd));
    for (int c = 0; c < 3; ++c) {
      const cv::Mat smooth = combined_kernel(k, w, c);
      const cv::Mat lined = k.core * w.core + with_wave_lines(line_part(k, w, c), p, c, 0.0);
      for (const double t : {1.0, 2.0, 5.0, 10.0}) {
        EXPECT_NEAR(within(lined, kPpd, t) / within(smooth, kPpd, t), 1.0, 0.02) << "age " << age << " at " << t;
        // The lines alone: only the half ring at t's edge may differ.
        const cv::Mat part = line_part(k, w, c);
        EXPECT_NEAR(within(with_wave_lines(part, p, c, 0.0), kPpd, t) / within(part, kPpd, t), 1.0, 1e-3)
            << "the line part, age " << age << " at " << t;
      }
      EXPECT_NEAR(cv::sum(lined)[0] / cv::sum(smooth)[0], 1.0, 1e-12) << "no light added";
      // The lines' contrast: the spread of lined / smooth about 1 on the
      // rings from 1 to 3 deg, with haze 0.3 (a hazy viewer's own PSF)
      // about 0.7 times that without.
      ViewerProfile hazy_viewer = viewer;
      hazy_viewer.haze = 0.3;
      const EyeOptics hazy_optics(hazy_viewer);
      const ComponentKernels hk = build_component_kernels(480, 480, kPpd, hazy_optics);
      const PsfWeights hw = hazy_optics.weights(age > 50 ? -3.0 : 2.0);
      const cv::Mat hazy_smooth = combined_kernel(hk, hw, c);
      const cv::Mat hazy = hk.core * hw.core + with_wave_lines(line_part(hk, hw, c), p, c, 0.3);
      double clear2 = 0, hazy2 = 0;
      for (int y = 0; y < smooth.rows; ++y)
        for (int x = 0; x < smooth.cols; ++x) {
          const double t = std::hypot(x - smooth.cols / 2, y - smooth.rows / 2) / kPpd;
          if (t < 1.0 || t > 3.0) continue;
          clear2 += std::pow(lined.at<double>(y, x) / smooth.at<double>(y, x) - 1.0, 2);
          hazy2 += std::pow(hazy.at<double>(y, x) / hazy_smooth.at<double>(y, x) - 1.0, 2);
        }
      EXPECT_GT(clear2, 0.0);
      EXPECT_NEAR(std::sqrt(hazy2 / clear2), 0.7, 0.07) << "haze 0.3 keeps about 70 % of the lines' contrast";
    }
  }
}

// Only a light at least 40 times its surround (the ring between the 2 deg
// and the 6 deg square around it) shows lines, a point or a lamp that
// fills much of the inner square alike.
TEST(WavePsf, LinesShowForLightsFortyTimesTheirSurround) {
  const EyeOptics optics;
  const WaveLines lines(optics, kPpd);
  const PsfWeights w = optics.weights(0.0);
  const auto draws = [&](const cv::Mat& rgb) {
    const cv::Mat before(rgb.size(), CV_32FC3, cv::Scalar::all(0.5));
    cv::Mat after = before.clone();
    const bool drew = lines.add(rgb, w, 4.0, 0.0, {rgb.cols / 2.0, rgb.rows / 2.0}, after);
    EXPECT_EQ(drew, cv::norm(before, after, cv::NORM_INF) > 0.0);
    return drew;
  };
  for (const double ratio : {30.0, 60.0}) {
    cv::Mat rgb(200, 300, CV_32FC3, cv::Scalar::all(1.0));
    rgb.at<cv::Vec3f>(100, 150) = cv::Vec3f::all(float(ratio));  // a point on a 1 cd/m^2 field
    EXPECT_EQ(draws(rgb), ratio > 40.0) << "a light " << ratio << " times its surround";
    cv::Mat bar(200, 300, CV_32FC3, cv::Scalar::all(1.0));
    bar(cv::Rect(150 - int(0.75 * kPpd), 99, int(1.5 * kPpd), 2)) = cv::Scalar::all(ratio);  // 1.5 by 0.09 deg
    EXPECT_EQ(draws(bar), ratio > 40.0) << "a lamp 1.5 deg long, " << ratio << " times its surround";
    cv::Mat sun(200, 300, CV_32FC3, cv::Scalar::all(1.0));
    cv::circle(sun, {150, 100}, int(0.27 * kPpd), cv::Scalar::all(ratio), cv::FILLED);  // the sun's disc
    EXPECT_EQ(draws(sun), ratio > 40.0) << "a 0.27 deg disc, " << ratio << " times its surround";
  }
}

// Frames finer than 35 px/deg (70 and 160: reduced by 2 and by 5), the
// lines spread by FFT and by scattering each light: the lines move light
// and add none, leave what lies beyond their reach alone, and are the
// same on one thread as on two.
TEST(WavePsf, OnFineFramesTheLinesMoveLightAddNoneAndDoNotDependOnThreads) {
  for (const double ppd : {70.0, 160.0})
    for (const WaveLines::Spread spread : {WaveLines::Spread::fft, WaveLines::Spread::scatter}) {
    const EyeOptics optics;
    WaveLines lines(optics, ppd);
    lines.set_spread(spread);
    const PsfWeights w = optics.weights(0.0);
    const int side = int(0.75 * ppd);  // a 0.75 deg square lamp: over 400 pixels after the reduction
    const cv::Size frame(int(10 * ppd), int(8 * ppd));
    cv::Mat rgb(frame, CV_32FC3, cv::Scalar::all(1.0));
    rgb(cv::Rect(frame.width / 2 - side / 2, frame.height / 2 - side / 2, side, side)) = cv::Scalar(2e4, 1.5e4, 1e4);
    const cv::Mat before(frame, CV_32FC3, cv::Scalar::all(1e3));  // (high: no clamping)
    cv::Mat after = before.clone(), one = before.clone();
    ASSERT_TRUE(lines.add(rgb, w, 4.0, 0.5, {frame.width / 2.0, frame.height / 2.0}, after));
    const int threads = cv::getNumThreads();
    cv::setNumThreads(1);
    lines.add(rgb, w, 4.0, 0.5, {frame.width / 2.0, frame.height / 2.0}, one);
    cv::setNumThreads(threads);
    EXPECT_EQ(cv::norm(after, one, cv::NORM_INF), 0.0) << ppd << " px/deg: one thread";
    cv::Mat separate;  // into another image, `before` untouched
    ASSERT_TRUE(lines.add(rgb, w, 4.0, 0.5, {frame.width / 2.0, frame.height / 2.0}, before, separate));
    EXPECT_EQ(cv::norm(after, separate, cv::NORM_INF), 0.0) << ppd << " px/deg: into a new image";
    EXPECT_EQ(cv::norm(before - cv::Scalar::all(1e3), cv::NORM_INF), 0.0);
    const cv::Mat delta = after - before;
    cv::Mat moved;
    cv::absdiff(after, before, moved);
    for (int c = 0; c < 3; ++c)
      EXPECT_LT(std::abs(cv::sum(delta)[c]), 1e-3 * cv::sum(moved)[c]) << ppd << " px/deg, channel " << c;
    EXPECT_GT(cv::sum(moved)[1], 0.0);
    // Beyond the lines' reach (3.6 deg and a pixel of the reduction) nothing.
    const int reach = int((kWavePatternReach_deg + 0.1) * ppd) + side / 2;
    const cv::Rect near(frame.width / 2 - reach, frame.height / 2 - reach, 2 * reach, 2 * reach);
    cv::Mat far = moved.clone();
    far(near & cv::Rect(0, 0, frame.width, frame.height)) = cv::Scalar::all(0);
    EXPECT_EQ(cv::norm(far, cv::NORM_INF), 0.0) << ppd << " px/deg";
  }
}

// A frame that is not whole blocks of the reduction (70 px/deg: by 2; 160:
// by 5) draws the lines of the same frame with black columns and rows
// added to make whole blocks: the lines do not shift.
TEST(WavePsf, FramesOfAnySizeDrawTheLinesInPlace) {
  for (const double ppd : {70.0, 160.0}) {
    const EyeOptics optics;
    const WaveLines lines(optics, ppd);
    const PsfWeights w = optics.weights(0.0);
    const int factor = ppd > 100 ? 5 : 2;
    const cv::Size whole(factor * 151, factor * 97), odd(whole.width - factor + 1, whole.height - factor + 1);
    cv::Mat big(whole, CV_32FC3, cv::Scalar::all(0.0));
    cv::Mat scene = big(cv::Rect(0, 0, odd.width, odd.height));
    scene.setTo(cv::Scalar::all(1.0));
    cv::circle(scene, {odd.width - 9, odd.height / 2}, 3, cv::Scalar(2e4, 1.5e4, 1e4), cv::FILLED);  // at the odd edge
    cv::Mat drawn_big(whole, CV_32FC3, cv::Scalar::all(1e3)), drawn(odd, CV_32FC3, cv::Scalar::all(1e3));
    const cv::Point2d gaze(odd.width / 2.0, odd.height / 2.0);
    ASSERT_TRUE(lines.add(big, w, 4.0, 0.5, gaze, drawn_big));
    ASSERT_TRUE(lines.add(scene.clone(), w, 4.0, 0.5, gaze, drawn));
    EXPECT_GT(cv::norm(drawn - cv::Scalar::all(1e3), cv::NORM_INF), 1.0) << ppd;
    EXPECT_EQ(cv::norm(drawn, drawn_big(cv::Rect(0, 0, odd.width, odd.height)), cv::NORM_INF), 0.0) << ppd << " px/deg";
  }
}

// The two ways of spreading the lines (an FFT of the lights' box, each
// light scattered) draw the same lines: a lamp and scattered points.
TEST(WavePsf, ScatteredAndFftLinesAgree) {
  const EyeOptics optics;
  const PsfWeights w = optics.weights(0.0);
  cv::Mat rgb(400, 600, CV_32FC3, cv::Scalar::all(1.0));
  rgb(cv::Rect(280, 190, 30, 12)) = cv::Scalar(3e4, 2e4, 1e4);
  cv::RNG rng(5);
  for (int i = 0; i < 25; ++i) rgb.at<cv::Vec3f>(rng.uniform(0, 400), rng.uniform(0, 600)) = cv::Vec3f::all(5e3f);
  const cv::Mat before(rgb.size(), CV_32FC3, cv::Scalar::all(1e3));
  cv::Mat drawn[2];
  for (int i = 0; i < 2; ++i) {
    WaveLines lines(optics, kPpd);
    lines.set_spread(i == 0 ? WaveLines::Spread::fft : WaveLines::Spread::scatter);
    drawn[i] = before.clone();
    ASSERT_TRUE(lines.add(rgb, w, 4.0, 0.2, {300.0, 200.0}, drawn[i]));
  }
  const double change = cv::norm(drawn[1], before, cv::NORM_INF);
  EXPECT_GT(change, 1.0);
  EXPECT_LT(cv::norm(drawn[0], drawn[1], cv::NORM_INF), 1e-3 * change);
}

}  // namespace
}  // namespace eyestream::glare
