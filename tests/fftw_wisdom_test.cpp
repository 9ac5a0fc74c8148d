// The FFTW wisdom shipped with the program (glare/fftw_planner.hpp): FFTW
// takes it, it holds the plans of the presets' 1080p transforms, and an
// engine whose transforms it plans still matches a direct sum computed here.
#include <gtest/gtest.h>

#include <fftw3.h>

#include "direct_convolution.hpp"
#include "glare/fft_convolver.hpp"
#include "glare/fftw_planner.hpp"
#include "glare/tiled_convolver.hpp"

namespace eyestream::glare {
namespace {

TEST(FftwWisdom, FftwTakesTheShippedText) {
  // Refused when Debian's FFTW is another build than the one the text was
  // made with: then remake it (scripts/fftw-wisdom.sh). Refused as well,
  // whole, on a CPU without AVX (FFTW registers other solvers there).
  if (!__builtin_cpu_supports("avx")) GTEST_SKIP() << "no AVX: FFTW refuses the shipped text here";
  EXPECT_TRUE(fftw_took_shipped_wisdom()) << "glare/fftw_wisdom.txt: FFTW refused it";
}

TEST(FftwWisdom, HoldsThePlansOfBalancedAt1080p) {
  // Its plans use FFTW's AVX code: elsewhere FFTW plans by estimate.
  if (!__builtin_cpu_supports("avx")) GTEST_SKIP() << "no AVX: FFTW cannot use the shipped plans here";
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  const unsigned only = fftw_plan_rigor() | FFTW_WISDOM_ONLY;  // a plan from wisdom or none
  // The near tiles (256 x 256, R = 16).
  double* real = fftw_alloc_real(256 * 256);
  fftw_complex* spectrum = fftw_alloc_complex(256 * 129);
  fftw_plan tile = fftw_plan_dft_r2c_2d(256, 256, real, spectrum, only);
  EXPECT_NE(tile, nullptr) << "the near tiles' forward transform";
  // The middle level: columns of 768 in blocks of 16, one after the other.
  int n = 768;
  fftw_complex* block = fftw_alloc_complex(size_t(n) * 16);
  fftw_plan columns = fftw_plan_many_dft(1, &n, 16, block, nullptr, 1, n, block, nullptr, 1, n, FFTW_FORWARD, only);
  EXPECT_NE(columns, nullptr) << "the middle level's column transforms";
  for (fftw_plan p : {tile, columns})
    if (p) fftw_destroy_plan(p);
  fftw_free(real);
  fftw_free(spectrum);
  fftw_free(block);
}

TEST(FftwWisdom, AnEngineOnTheShippedPlansMatchesTheDirectSum) {
  // 1188 x 756 with a 13 px kernel: transforms of 1200 x 768, the middle
  // level's at 1080p in `balanced`, planned from the wisdom.
  const ComponentKernels k = test::random_kernels(6, 3);
  PsfWeights w;
  w.core = 0.6, w.inner = 0.2, w.outer = 0.15, w.halo = 0.05;
  cv::Mat in(756, 1188, CV_32FC3);
  cv::RNG(5).fill(in, cv::RNG::UNIFORM, 0.0, 100.0);
  const FftConvolver engine(k, in.cols, in.rows);
  ASSERT_EQ(engine.transform_size(), cv::Size(1200, 768));
  cv::Mat got, got64;
  engine.convolve(in, w, got);
  got.convertTo(got64, CV_64FC3);
  EXPECT_LT(cv::norm(got64, test::direct_convolution(in, k, w), cv::NORM_INF), 1e-4);  // values near 100, as float
}

}  // namespace
}  // namespace eyestream::glare
