// Glare cost per frame by engine (Google Benchmark; never asserts), full
// image with the surround scattered in (the default mode): the
// exact FFT engine (Vos and CIE PSFs), the split engine (tail at 1/2 and
// 1/4 resolution) and Yoshida et al. 2008's Gaussian, on a frame with lights above the
// display peak, plus the one-time kernel build with and without flare lines.
#include <benchmark/benchmark.h>

#include "glare/split_convolver.hpp"
#include "glare/wave_lines.hpp"
#include "pipeline/memory/frame_buffer_pool.hpp"
#include "pipeline/eye/glare_stage.hpp"
#include "pipeline/settings/quality_presets.hpp"

namespace {

using namespace eyestream;

// engine: "exact", "split2", "split4", "gaussian", or a preset's glare
// ("preset:fast", "preset:balanced"); model: "vos" or "cie".
pipeline::Plan plan_for(int width, const std::string& engine, const std::string& model = "vos",
                        bool flare_lines = true) {
  pipeline::Settings s;
  if (engine.rfind("preset:", 0) == 0) {
    pipeline::apply_quality_preset(engine.substr(7), s);
    s.skip = false;
    io::SourceInfo info;
    info.width = width;
    info.height = width * 9 / 16;
    info.frames_per_second = 30;
    return pipeline::compile_plan(s, info);
  }
  s.psf_model = engine == "gaussian" ? "gaussian" : model;
  s.flare_lines = flare_lines;
  s.skip = false;  // the same frame every iteration: not the still-frame cache
  s.glare_engine = engine.rfind("split", 0) == 0 ? "split" : "exact";
  if (s.glare_engine == "split") s.glare_tail_factor = engine.back() - '0';
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

void BM_GlareFrame(benchmark::State& state, const std::string& engine, const std::string& model) {
  const int width = int(state.range(0));
  pipeline::reuse_frame_buffers();  // as the program does
  pipeline::GlareStage stage(plan_for(width, engine, model));
  const cv::Mat frame = night_frame(width);
  for (auto _ : state) benchmark::DoNotOptimize(stage.apply(frame, -1.0, 0.3));
  state.SetItemsProcessed(state.iterations() * width * (width * 9 / 16));
}

// The one-time kernel build (and FFT spectra) of the exact engine.
void BM_KernelBuild(benchmark::State& state, const std::string& model, bool flare_lines) {
  const int width = int(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(pipeline::GlareStage(plan_for(width, "exact", model, flare_lines)));
}

// The wave-optics lines (--flare-model wave) alone, at 1080p and 37
// px/deg (drawn at half that): the pattern for one state, and the lines
// of a frame's lights, few (scattered) or many (by FFT).
constexpr double kWavePpd = 37.0;

// range(0): the upper lid's MRD1 in tenths of a mm (0: none), under a
// 6 mm pupil.
void BM_WavePattern(benchmark::State& state) {
  pipeline::reuse_frame_buffers();  // as the program does
  const glare::WaveAperture aperture = glare::viewer_aperture(1, state.range(0) / 10.0);
  glare::WaveState s;
  s.pupil_mm = 6.0;
  double t = 0.0;
  for (auto _ : state) {
    s.time_s = t += 1.0 / 30.0;
    benchmark::DoNotOptimize(glare::wave_pattern(aperture, s, kWavePpd / 2, int(3.6 * kWavePpd / 2)));
  }
}

void BM_WaveLines(benchmark::State& state) {
  const int lights = int(state.range(0));
  pipeline::reuse_frame_buffers();  // as the program does
  const glare::EyeOptics optics;
  const glare::WaveLines lines(optics, kWavePpd);
  const glare::PsfWeights w = optics.weights(0.0);
  cv::Mat frame(1080, 1920, CV_32FC3, cv::Scalar::all(0.3));
  cv::RNG rng(3);
  for (int i = 0; i < lights; ++i)
    frame.at<cv::Vec3f>(rng.uniform(0, 1080), rng.uniform(0, 1920)) = cv::Vec3f::all(float(rng.uniform(1e3, 1e6)));
  const cv::Mat retinal(frame.size(), CV_32FC3, cv::Scalar::all(1.0));
  cv::Mat out;  // the smooth glare kept, the lines into a new image (as with the still-frame cache)
  double t = 0.0;
  for (auto _ : state) benchmark::DoNotOptimize(lines.add(frame, w, 4.0, t += 1.0 / 30.0, {960, 540}, retinal, out));
}

// The split engine alone (balanced's: middle level at 1/2) on a 1080p frame
// that is 0 but for range(0) lights: the near field scattered directly
// while the lights are few, by a full-frame FFT beyond that.
void BM_SplitLights(benchmark::State& state) {
  const int lights = int(state.range(0));
  pipeline::reuse_frame_buffers();  // as the program does
  const glare::EyeOptics optics;
  const glare::SplitConvolver split(1920, 1080, 32.0, 2, optics);
  const glare::PsfWeights w = optics.weights(0.0);
  cv::Mat frame(1080, 1920, CV_32FC3, cv::Scalar::all(0.0));
  cv::RNG rng(3);
  for (int i = 0; i < lights; ++i)
    frame.at<cv::Vec3f>(rng.uniform(0, 1080), rng.uniform(0, 1920)) = cv::Vec3f::all(float(rng.uniform(1e3, 1e6)));
  for (auto _ : state) benchmark::DoNotOptimize(split.convolve(frame, w));
}

void widths(benchmark::internal::Benchmark* b) {
  b->Arg(640)->Arg(1280)->Arg(1920)->Unit(benchmark::kMillisecond)->UseRealTime();
}

void build_widths(benchmark::internal::Benchmark* b) {
  b->Arg(640)->Arg(1920)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
}

BENCHMARK_CAPTURE(BM_GlareFrame, vos_fft, std::string("exact"), std::string("vos"))->Apply(widths);
BENCHMARK_CAPTURE(BM_GlareFrame, cie_fft, std::string("exact"), std::string("cie"))->Apply(widths);
BENCHMARK_CAPTURE(BM_GlareFrame, vos_split2, std::string("split2"), std::string("vos"))->Apply(widths);
BENCHMARK_CAPTURE(BM_GlareFrame, vos_split4, std::string("split4"), std::string("vos"))->Apply(widths);
BENCHMARK_CAPTURE(BM_GlareFrame, balanced, std::string("preset:balanced"), std::string("vos"))->Apply(widths);
BENCHMARK_CAPTURE(BM_GlareFrame, fast, std::string("preset:fast"), std::string("vos"))->Apply(widths);
BENCHMARK_CAPTURE(BM_GlareFrame, gaussian, std::string("gaussian"), std::string("vos"))->Apply(widths);
BENCHMARK(BM_SplitLights)->Arg(0)->Arg(900)->Arg(1100)->Arg(8000)->Arg(30000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_WavePattern)->Arg(0)->Arg(15)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_WaveLines)->Arg(40)->Arg(2000)->Arg(20000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_KernelBuild, vos_flare_lines, std::string("vos"), true)->Apply(build_widths);
BENCHMARK_CAPTURE(BM_KernelBuild, vos_plain, std::string("vos"), false)->Apply(build_widths);
BENCHMARK_CAPTURE(BM_KernelBuild, cie_flare_lines, std::string("cie"), true)->Apply(build_widths);

}  // namespace

BENCHMARK_MAIN();
