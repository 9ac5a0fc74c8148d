// The FFT engine (glare/fft_convolver.hpp) against a direct sum computed
// here, for kernels smaller than the frame (padding by the kernel's reach
// only), and its rounding on a night road beside a headlight 10^7 times
// brighter (which single precision failed: 0.0021 cd/m^2 on 0.01).
#include <gtest/gtest.h>

#include <cmath>

#include "direct_convolution.hpp"
#include "glare/fft_convolver.hpp"

namespace eyestream::glare {
namespace {

using test::direct_convolution;
using test::random_kernels;

// The largest difference of `engine`'s output for a random frame (values
// 0 to 100) from the direct sum.
double error_against_direct_sum(const FftConvolver& engine, cv::Size size, const ComponentKernels& k,
                                const PsfWeights& w, int seed) {
  cv::Mat in(size, CV_32FC3);
  cv::RNG(seed).fill(in, cv::RNG::UNIFORM, 0.0, 100.0);
  cv::Mat got, got64;
  engine.convolve(in, w, got);
  got.convertTo(got64, CV_64FC3);
  return cv::norm(got64, direct_convolution(in, k, w), cv::NORM_INF);
}

// Each channel with its own halo kernel. The engine holds the three
// channels' spectra at once when they take at most 16 MiB (`fast`'s near
// plane), else one after the other: 880 x 880 is transformed at 896 x
// 896, three spectra of 896 x 464 values (whole blocks of 16 columns)
// taking 20 MB, so one at a time; both ways match the direct sum.
TEST(FftConvolver, SmallKernelsMatchTheDirectSum) {
  const ComponentKernels k = random_kernels(5, 7);
  PsfWeights w;
  w.core = 0.7, w.inner = 0.1, w.outer = 0.15, w.halo = 0.05;
  for (cv::Size size : {cv::Size(37, 23), cv::Size(64, 40), cv::Size(880, 880)}) {
    const FftConvolver engine(k, size.width, size.height);
    EXPECT_GE(engine.transform_size().width, size.width + 5);
    EXPECT_LT(engine.transform_size().width, 2 * size.width) << "padded by the kernel's reach, not the frame's";
    EXPECT_EQ(engine.channels_at_once(), size.width == 880 ? 1 : 3) << size;
    EXPECT_LT(error_against_direct_sum(engine, size, k, w, 11), 1e-4) << size;  // values near 100, stored as float
  }
}

// Transform sizes: the smallest n >= the minimum whose prime factors are
// 2, 3, 5 and 7, and from 64 up a multiple of 16 as well (found here by
// trial over every candidate).
TEST(FftConvolver, TransformSizesAreSmoothMultiplesOfSixteen) {
  const auto smooth = [](int n) {
    for (int q : {2, 3, 5, 7})
      while (n % q == 0) n /= q;
    return n == 1;
  };
  for (int minimum = 1; minimum <= 5000; ++minimum) {
    int want = minimum;
    while (!smooth(want) || (minimum >= 64 && want % 16 != 0)) ++want;
    ASSERT_EQ(fft_size(minimum), want) << minimum;
  }
  EXPECT_EQ(fft_size(1248), 1280);  // `balanced`'s middle level at 1080p until the
  EXPECT_EQ(fft_size(828), 864);    // fourteenth session, across and down (was 1250 x 840)
  EXPECT_EQ(fft_size(1156), 1200);  // since then (the tail's narrower ramp)
  EXPECT_EQ(fft_size(756), 768);
  EXPECT_EQ(fft_size(3839), 3840);  // `reference`'s at 1080p, unchanged
  EXPECT_EQ(fft_size(2159), 2160);
}

TEST(FftConvolver, RefusesAKernelThatIsNotPointSymmetric) {
  // Only real spectra are kept: a kernel with a complex spectrum would be
  // convolved as its symmetric part, so it is refused instead.
  EXPECT_THROW(FftConvolver(random_kernels(5, 7, false), 37, 23), cv::Exception);
  EXPECT_NO_THROW(FftConvolver(random_kernels(5, 7), 37, 23));
}

TEST(FftConvolver, KeepsANightRoadBesideAHeadlight) {
  // A 0.01 cd/m^2 road, one 1e5 cd/m^2 headlight pixel, a 33 px kernel that
  // falls as 1/r^3 (a PSF's shape). Beyond the headlight's reach the road
  // keeps its 0.01 cd/m^2 less what the kernel spreads off the frame near
  // its edges: within 1e-6 of the direct sum in the rows and columns checked.
  const int r = 16;
  const cv::Mat in = test::road_with_headlight(320, 180);
  cv::Mat out;
  FftConvolver(test::falloff_kernels(r), in.cols, in.rows).convolve(in, test::core_only(), out);
  EXPECT_LT(test::worst_road_error(out, r), 1e-6) << "rounding on a 0.01 cd/m^2 road beside 1e5 cd/m^2";
}

}  // namespace
}  // namespace eyestream::glare
