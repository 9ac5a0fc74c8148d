// Per-stage cost of one 1080p frame (Google Benchmark; never asserts), with
// the frame loop's pooled buffers.
// Run: build/bench/eyestream_stage_bench
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "pipeline/memory/frame_buffer_pool.hpp"
#include "retina/acuity_loss.hpp"
#include "retina/afterimage_composite.hpp"
#include "retina/display_encoding.hpp"
#include "retina/luminance_field.hpp"
#include "retina/tone_curve.hpp"
#include "retina/tone_map.hpp"

namespace {

using namespace eyestream;

cv::Mat hdr_frame(int width, int height) {
  cv::Mat frame(height, width, CV_32FC3);
  cv::RNG rng(1);
  cv::Mat log_l(height, width, CV_32F);
  rng.fill(log_l, cv::RNG::UNIFORM, -3.0, 5.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float l = std::pow(10.0f, log_l.at<float>(y, x));
      frame.at<cv::Vec3f>(y, x) = cv::Vec3f(l, l, l);
    }
  return frame;
}

void set_threads(const benchmark::State& state) { cv::setNumThreads(int(state.range(0))); }

void BM_LuminanceField(benchmark::State& state) {
  set_threads(state);
  const cv::Mat frame = hdr_frame(1920, 1080);
  for (auto _ : state) {
    retina::LuminanceField field(frame, 1e-6);
    benchmark::DoNotOptimize(field.patch_log_mean(960, 540, 48, 1.0));
  }
  state.SetItemsProcessed(state.iterations() * 1920 * 1080);
}

void BM_ToneMap(benchmark::State& state) {
  set_threads(state);
  const cv::Mat frame = hdr_frame(1920, 1080);
  const retina::ToneCurve curve(1.0, retina::ToneCurveParams{});
  cv::Mat out;
  for (auto _ : state) retina::tone_map(frame, curve, out);
  state.SetItemsProcessed(state.iterations() * 1920 * 1080);
}

void BM_EncodeDithered8(benchmark::State& state) {
  set_threads(state);
  cv::Mat linear(1080, 1920, CV_32FC3);
  cv::randu(linear, 0.0, 1.0);
  cv::Mat code;
  std::int64_t frame = 0;
  for (auto _ : state) retina::encode_display(linear, 8, frame++, retina::EncodingParams{}, code);
  state.SetItemsProcessed(state.iterations() * 1920 * 1080);
}

// The afterimage composite of a 1080p frame: maps the frame's size
// (argument 1) or reduced to a quarter each way (4), as `fast` draws them
// under the rectilinear projection; a third of their rows at rest.
void BM_AfterimageComposite(benchmark::State& state) {
  cv::setNumThreads(2);
  const int reduce = int(state.range(0));
  cv::Mat tone(1080, 1920, CV_32FC3), gain(1080 / reduce, 1920 / reduce, CV_32FC3), bleach(gain.size(), CV_32FC3);
  cv::randu(tone, 0.0, 1.0);
  cv::randu(gain, -0.3, 0.3);
  cv::randu(bleach, -0.01, 0.01);
  for (int y = 0; y < gain.rows; y += 3) gain.row(y).setTo(0.0), bleach.row(y).setTo(0.0);
  cv::Mat out;
  for (auto _ : state) retina::composite_afterimages(tone, gain, bleach, out);
  state.SetItemsProcessed(state.iterations() * 1920 * 1080);
}

// The acuity loss of a 1080p frame at 37 px/deg (the default viewing of a
// 1920 px frame), every pixel mesopic (rho 0.3 plus the noise), two
// threads, by pyramid_from_px x 10: 0 reference, 25 balanced, 12 fast (balanced 60
// and fast 15 until 2026-12-05).
void BM_AcuityLoss(benchmark::State& state) {
  cv::setNumThreads(2);
  retina::AcuityParams params;
  params.pyramid_from_px = double(state.range(0)) / 10.0;
  const retina::AcuityLoss loss(params, 37.0, 1);
  cv::Mat image(1080, 1920, CV_32FC3);
  cv::randu(image, 0.0, 1.0);
  const int f = loss.level_factor(image.size());
  const cv::Mat rho((image.rows + f - 1) / f, (image.cols + f - 1) / f, CV_32F, cv::Scalar(0.3));
  double t = 0.0;
  cv::Mat out;
  for (auto _ : state) {  // the level map held reduced, as the mesopic stage gives it
    image.copyTo(out);
    loss.apply(out, loss.level(rho, t += 1.0 / 30, 0.0, 0.0, f));
  }
  state.SetItemsProcessed(state.iterations() * 1920 * 1080);
}

BENCHMARK(BM_LuminanceField)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ToneMap)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_EncodeDithered8)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_AfterimageComposite)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_AcuityLoss)->Arg(0)->Arg(25)->Arg(12)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

// The frame loop's buffers come from the pool (frame_buffer_pool.hpp).
int main(int argc, char** argv) {
  eyestream::pipeline::reuse_frame_buffers();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
