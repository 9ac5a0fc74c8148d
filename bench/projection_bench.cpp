// Cost of carrying a 1080p frame to the angle plane and back, and of the
// retina's gaze positions (Google Benchmark; never asserts).
// Run: build/bench/eyestream_projection_bench
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>

#include "pipeline/geometry/frame_projection.hpp"

namespace {

using namespace eyestream;

// The default viewing condition (29.3 deg) and a simulator's 120 deg.
const pipeline::FrameProjection& projection(int fov) {
  static const pipeline::FrameProjection narrow(1920, 1080, 29.3, pipeline::Projection::rectilinear),
      wide(1920, 1080, 120.0, pipeline::Projection::rectilinear);
  return fov == 120 ? wide : narrow;
}

cv::Mat frame_of(cv::Size size) {
  cv::Mat f(size, CV_32FC3);
  cv::randu(f, cv::Scalar::all(0.0), cv::Scalar::all(100.0));
  return f;
}

void BM_ToPlaneFlux(benchmark::State& state) {
  const pipeline::FrameProjection& p = projection(int(state.range(0)));
  const cv::Mat frame = frame_of(p.frame_size());
  p.make_carriage_now();  // (made on first use: not timed)
  for (auto _ : state) benchmark::DoNotOptimize(p.to_plane_flux(frame).data);
}

void BM_ToFrameImage(benchmark::State& state) {
  const pipeline::FrameProjection& p = projection(int(state.range(0)));
  const cv::Mat plane = frame_of(p.plane_size());
  p.make_carriage_now();  // (made on first use: not timed)
  for (auto _ : state) benchmark::DoNotOptimize(p.to_frame_image(plane).data);
}

void BM_GazePositions(benchmark::State& state) {
  const pipeline::FrameProjection& p = projection(int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(p.gaze_positions({1200, 400}, p.frame_size(), 0.5, {1000, 600}).data);
}

BENCHMARK(BM_ToPlaneFlux)->Arg(29)->Arg(120)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ToFrameImage)->Arg(29)->Arg(120)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_GazePositions)->Arg(29)->Arg(120)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
