// Glare cost per frame by engine (Google Benchmark; never asserts): the
// exact Vos FFT engine and seed 003's Gaussian, on a frame with lights
// above the display peak, plus the one-time kernel build.
#include <benchmark/benchmark.h>

#include "pipeline/glare_stage.hpp"

namespace {

using namespace eyestream;

pipeline::Plan plan_for(int width, const std::string& model) {
  pipeline::Settings s;
  s.psf_model = model;
  io::SourceInfo info;
  info.width = width;
  info.height = width * 9 / 16;
  info.frames_per_second = 30;
  return pipeline::compile_plan(s, info);
}

cv::Mat night_frame(int width) {
  const int height = width * 9 / 16;
  cv::Mat frame(height, width, CV_32FC3, cv::Scalar::all(0.3));
  cv::RNG rng(3);
  for (int i = 0; i < 40; ++i)
    frame.at<cv::Vec3f>(rng.uniform(0, height), rng.uniform(0, width)) = cv::Vec3f::all(float(rng.uniform(1e3, 1e6)));
  return frame;
}

void BM_GlareFrame(benchmark::State& state, const std::string& model) {
  const int width = int(state.range(0));
  const pipeline::GlareStage stage(plan_for(width, model));
  const cv::Mat frame = night_frame(width);
  for (auto _ : state) benchmark::DoNotOptimize(stage.apply(frame, -1.0));
  state.SetItemsProcessed(state.iterations() * width * (width * 9 / 16));
}

void BM_VosKernelBuild(benchmark::State& state) {
  const int width = int(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(pipeline::GlareStage(plan_for(width, "vos")));
}

BENCHMARK_CAPTURE(BM_GlareFrame, vos_fft, std::string("vos"))
    ->Arg(640)
    ->Arg(1280)
    ->Arg(1920)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_GlareFrame, gaussian, std::string("gaussian"))
    ->Arg(640)
    ->Arg(1280)
    ->Arg(1920)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_VosKernelBuild)->Arg(640)->Arg(1920)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
