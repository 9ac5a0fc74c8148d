// Retina state cost per frame (Google Benchmark; never asserts): the eye
// without optics (adaptation, one exact step of every site, the afterimage
// maps, the tone map) for full and reduced state resolution. Items are
// frame pixels, so items/s reads as pixels/s.
#include <benchmark/benchmark.h>

#include "pipeline/eye/eye_simulator.hpp"

namespace {

using namespace eyestream;

void BM_RetinaFrame(benchmark::State& state) {
  const int width = int(state.range(0)), height = width * 9 / 16;
  pipeline::Settings s;
  s.state_sites_per_pixel = double(state.range(1)) / 100.0;
  s.state_least_sites_per_deg = 0.0;  // the resolution asked for, not raised by balanced's floor
  s.glare = false;  // timed by eyestream_glare_bench
  io::SourceInfo info;
  info.width = width;
  info.height = height;
  info.frames_per_second = 30;
  pipeline::EyeSimulator eye(pipeline::compile_plan(s, info));
  cv::Mat frame(height, width, CV_32FC3);
  cv::randu(frame, 0.0, 1000.0);
  std::int64_t index = 0;
  for (auto _ : state) {
    const double t = index / 30.0;
    io::SceneFrame f{frame, t, index++, "bench"};
    benchmark::DoNotOptimize(eye.process(f, {{t, t + 1 / 30.0, width / 2.0 + (index % 7), height / 2.0, false}}));
  }
  state.SetItemsProcessed(state.iterations() * width * height);
  state.counters["sites_per_px"] = s.state_sites_per_pixel;
}

// Whole eye per 1080p frame at state resolution 1, 0.5 and 0.25.
BENCHMARK(BM_RetinaFrame)
    ->Args({1920, 100})
    ->Args({1920, 50})
    ->Args({1920, 25})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
