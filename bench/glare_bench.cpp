// Glare cost per frame by engine (Google Benchmark; never asserts): the
// exact Vos FFT engine, the split engine (tail at 1/2 and 1/4 resolution)
// and seed 003's Gaussian, on a frame with lights above the display peak,
// plus the one-time kernel build.
#include <benchmark/benchmark.h>

#include "pipeline/glare_stage.hpp"

namespace {

using namespace eyestream;

// model: "vos" (exact), "split2", "split4" or "gaussian".
pipeline::Plan plan_for(int width, const std::string& model) {
  pipeline::Settings s;
  s.psf_model = model == "gaussian" ? "gaussian" : "vos";
  s.glare_engine = model.rfind("split", 0) == 0 ? "split" : "exact";
  if (s.glare_engine == "split") s.glare_tail_factor = model.back() - '0';
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

void widths(benchmark::internal::Benchmark* b) {
  b->Arg(640)->Arg(1280)->Arg(1920)->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK_CAPTURE(BM_GlareFrame, vos_fft, std::string("vos"))->Apply(widths);
BENCHMARK_CAPTURE(BM_GlareFrame, vos_split2, std::string("split2"))->Apply(widths);
BENCHMARK_CAPTURE(BM_GlareFrame, vos_split4, std::string("split4"))->Apply(widths);
BENCHMARK_CAPTURE(BM_GlareFrame, gaussian, std::string("gaussian"))->Apply(widths);
BENCHMARK(BM_VosKernelBuild)->Arg(640)->Arg(1920)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
