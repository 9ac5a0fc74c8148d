// The tiled FFT engine (glare/tiled_convolver.hpp) against a direct sum
// computed here (direct_convolution.hpp): frames of several tiles whose
// sizes are not whole tiles, sparse light that leaves whole tiles unlit,
// its rounding beside a headlight, and results the same on any number of
// threads. Its tile size against the cost it is chosen by.
#include <gtest/gtest.h>

#include <cmath>

#include "direct_convolution.hpp"
#include "glare/split_convolver.hpp"
#include "glare/tiled_convolver.hpp"

namespace eyestream::glare {
namespace {

using test::direct_convolution;
using test::random_kernels;

PsfWeights some_weights() {
  PsfWeights w;
  w.core = 0.7, w.inner = 0.1, w.outer = 0.15, w.halo = 0.05;
  return w;
}

double worst_difference(const cv::Mat& got, const cv::Mat& want) {
  cv::Mat got64;
  got.convertTo(got64, CV_64FC3);
  return cv::norm(got64, want, cv::NORM_INF);
}

TEST(TiledConvolver, TileSizeIsTheCheapestPowerOfTwo) {
  // Work per output pixel T^2 log2(T^2) / (T - 2R)^2, computed here.
  const auto cost = [](int t, int r) { return t * t * std::log2(double(t) * t) / std::pow(t - 2.0 * r, 2); };
  EXPECT_EQ(tile_size_for(16), 256);  // the split engine's near part at factor 2
  EXPECT_LT(cost(256, 16), cost(128, 16));
  EXPECT_EQ(tile_size_for(5), 128);
  EXPECT_LT(cost(128, 5), cost(64, 5));
  EXPECT_LT(cost(128, 5), cost(256, 5));
  EXPECT_EQ(tile_size_for(32), 256);  // 512 would not stay in cache
  EXPECT_EQ(tile_size_for(100), 512);
  EXPECT_GT(tile_size_for(300) - 600, tile_size_for(300) / 4 - 1);  // no tile of no output
  EXPECT_NEAR(tile_output_share(16), std::pow(224.0 / 256.0, 2), 1e-12);
}

TEST(TiledConvolver, MatchesTheDirectSumOverSeveralTiles) {
  const PsfWeights w = some_weights();
  for (int r : {5, 16}) {
    const ComponentKernels k = random_kernels(r, 7);
    const TiledConvolver engine(k, 1, 1);
    const int block = engine.tile_size() - 2 * r;
    // Two and a bit tiles across, one and a bit down: every edge case of
    // a tile's window (frame edges, neighbours' rows).
    const cv::Size size(2 * block + 17, block + 9);
    cv::Mat in(size, CV_32FC3);
    cv::RNG(11).fill(in, cv::RNG::UNIFORM, 0.0, 100.0);
    cv::Mat got;
    TiledConvolver(k, size.width, size.height).convolve(in, same_in_every_channel(w), got);
    EXPECT_LT(worst_difference(got, direct_convolution(in, k, w)), 1e-4) << "r " << r;  // values near 100, as float
  }
  // A frame smaller than one tile's output block.
  const ComponentKernels k = random_kernels(5, 9);
  cv::Mat in(23, 37, CV_32FC3), got;
  cv::RNG(4).fill(in, cv::RNG::UNIFORM, 0.0, 100.0);
  TiledConvolver(k, in.cols, in.rows).convolve(in, same_in_every_channel(w), got);
  EXPECT_LT(worst_difference(got, direct_convolution(in, k, w)), 1e-4) << "one partial tile";
}

TEST(TiledConvolver, UnlitTilesAndChannelsStayDark) {
  // One light near a tile's edge, in red only: its reach crosses into the
  // next tile; the tiles it does not reach and the other channels are 0.
  const int r = 5;
  const ComponentKernels k = random_kernels(r, 3);
  const int block = TiledConvolver(k, 1, 1).tile_size() - 2 * r;
  const cv::Size size(3 * block, 2 * block);
  cv::Mat in = cv::Mat::zeros(size, CV_32FC3);
  in.at<cv::Vec3f>(block / 2, block - 2)[0] = 1e4f;
  cv::Mat got;
  TiledConvolver(k, size.width, size.height).convolve(in, same_in_every_channel(some_weights()), got);
  EXPECT_LT(worst_difference(got, direct_convolution(in, k, some_weights())), 1e-3);
  std::vector<cv::Mat> channels;
  cv::split(got, channels);
  EXPECT_EQ(cv::countNonZero(channels[1]), 0);
  EXPECT_EQ(cv::countNonZero(channels[2]), 0);
  EXPECT_GT(cv::countNonZero(channels[0](cv::Rect(block, 0, block, block))), 0) << "spread into the next tile";
  EXPECT_EQ(cv::countNonZero(channels[0](cv::Rect(2 * block, 0, block, 2 * block))), 0);
  EXPECT_EQ(cv::countNonZero(channels[0](cv::Rect(0, block, 3 * block, block))), 0);
}

TEST(TiledConvolver, InteriorTilesReuseTheirArraysWithoutStaleLight) {
  // Four tiles each way on one thread, so one thread's arrays go from
  // edge tiles (windows cut by the frame) to whole interior windows and
  // back: red light only in one interior tile, green only in the next,
  // -0 everywhere else. Every pixel matches the direct sum, and no light
  // reaches, nor a -0 leaves, where none was.
  const int r = 5;
  const ComponentKernels k = random_kernels(r, 13);
  const int block = TiledConvolver(k, 1, 1).tile_size() - 2 * r;
  const cv::Size size(4 * block, 4 * block);
  cv::Mat in(size, CV_32FC3, cv::Scalar::all(-0.0));
  cv::RNG rng(8);
  const cv::Rect red(block + 2 * r, block + 2 * r, block - 4 * r, block - 4 * r);
  const cv::Rect green = red + cv::Point(block, 0);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      if (red.contains({x, y})) in.at<cv::Vec3f>(y, x)[0] = rng.uniform(1.0f, 100.0f);
      if (green.contains({x, y})) in.at<cv::Vec3f>(y, x)[1] = rng.uniform(1.0f, 100.0f);
    }
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  cv::Mat got;
  TiledConvolver(k, size.width, size.height).convolve(in, same_in_every_channel(some_weights()), got);
  cv::setNumThreads(threads);
  EXPECT_LT(worst_difference(got, direct_convolution(in, k, some_weights())), 1e-4);
  int negative_zeros = 0;
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x)
      for (int c = 0; c < 3; ++c) negative_zeros += std::signbit(got.at<cv::Vec3f>(y, x)[c]) ? 1 : 0;
  EXPECT_EQ(negative_zeros, 0);
  std::vector<cv::Mat> channels;
  cv::split(got, channels);
  EXPECT_EQ(cv::countNonZero(channels[2]), 0) << "blue: no light anywhere";
  // Each light lies in one tile's window only (2R inside its block), so
  // the other tiles are exactly 0 in its channel (within its own tile the
  // FFT leaves rounding residue, which the direct sum bounds above).
  const cv::Rect red_tile(block, block, block, block), green_tile = red_tile + cv::Point(block, 0);
  EXPECT_EQ(cv::countNonZero(channels[0]) - cv::countNonZero(channels[0](red_tile)), 0) << "red in other tiles";
  EXPECT_EQ(cv::countNonZero(channels[1]) - cv::countNonZero(channels[1](green_tile)), 0) << "green in other tiles";
  EXPECT_GT(cv::countNonZero(channels[0](red)), red.area() / 2);
  EXPECT_GT(cv::countNonZero(channels[1](green)), green.area() / 2);
}

TEST(TiledConvolver, KeepsANightRoadBesideAHeadlight) {
  // As the whole-frame engine's test, over several tiles.
  const int r = 16;
  const cv::Mat in = test::road_with_headlight(640, 300);
  cv::Mat out;
  TiledConvolver(test::falloff_kernels(r), in.cols, in.rows).convolve(in, same_in_every_channel(test::core_only()), out);
  EXPECT_LT(test::worst_road_error(out, r), 1e-6) << "rounding on a 0.01 cd/m^2 road beside 1e5 cd/m^2";
}

TEST(TiledConvolver, SameResultOnAnyNumberOfThreads) {
  const ComponentKernels k = random_kernels(16, 5);
  const cv::Size size(700, 400);
  cv::Mat in(size, CV_32FC3);
  cv::RNG(2).fill(in, cv::RNG::UNIFORM, 0.0, 1e3);
  const TiledConvolver engine(k, size.width, size.height);
  const int threads = cv::getNumThreads();
  cv::Mat one, many;
  cv::setNumThreads(1);
  engine.convolve(in, same_in_every_channel(some_weights()), one);
  cv::setNumThreads(4);
  engine.convolve(in, same_in_every_channel(some_weights()), many);
  cv::setNumThreads(threads);
  EXPECT_EQ(cv::norm(one, many, cv::NORM_INF), 0.0);
}

TEST(TiledConvolver, RefusesAKernelThatIsNotPointSymmetric) {
  EXPECT_THROW(TiledConvolver(random_kernels(5, 7, false), 37, 23), cv::Exception);
}

}  // namespace
}  // namespace eyestream::glare
