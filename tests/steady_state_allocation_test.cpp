// What the steady-state frame loop asks of the allocator: the eye's frame
// (every stage running: the night city, lights above the display peak and
// a wandering gaze) and its display encoding, after a few frames have
// warmed the loop up, counted by replacing malloc (counting_malloc.hpp)
// and by the image pool (which maps its blocks of 2 MiB or more itself,
// unseen by malloc). No image-sized block may come from the system once
// the loop runs; small blocks are counted and bounded.
#include <gtest/gtest.h>

#include <cstdio>

#include "pipeline/api/eye_access.hpp"
#include "pipeline/bench/bench_scene.hpp"
#include "pipeline/memory/frame_buffer_pool.hpp"
#include "pipeline/settings/quality_presets.hpp"
#include "retina/display_encoding.hpp"
#include "tests/counting_malloc.hpp"

namespace eyestream {
namespace {

constexpr int kWarmUp = 6;

// The allocator's count, and the blocks the pool maps itself (2 MiB or
// more, unseen by malloc), over the same frames.
struct SteadyState {
  test::AllocationCount malloc;
  unsigned long mapped_blocks = 0;
};

SteadyState steady_state(const pipeline::BenchScene& scene, const std::string& preset) {
  pipeline::Settings settings;
  pipeline::apply_quality_preset(preset, settings);
  settings.skip = false;  // every stage every frame
  Eye eye = detail::EyeAccess::make(settings, scene.info);
  detail::EyeAccess::set_gaze(eye, std::make_shared<const pipeline::GazeTimeline>(
                                       scene.gaze, scene.info.width / 2.0, scene.info.height / 2.0));
  const pipeline::Plan& plan = detail::EyeAccess::plan(eye);
  cv::Mat code;
  unsigned long mapped_before = 0;
  for (size_t i = 0; i < scene.frames.size(); ++i) {
    if (i == kWarmUp) {
      mapped_before = pipeline::frame_buffers_mapped();
      test::start_counting_allocations();
    }
    io::DisplayFrame out = detail::EyeAccess::process(eye, scene.frames[i], scene.ends_s[i]);
    retina::encode_display(out.linear, 8, scene.frames[i].index, plan.encoding, code);
  }
  SteadyState s;
  s.malloc = test::stop_counting_allocations();
  s.mapped_blocks = pipeline::frame_buffers_mapped() - mapped_before;
  return s;
}

TEST(SteadyStateAllocation, TheFrameLoopTakesNoImageSizedBlockFromTheSystem) {
  pipeline::reuse_frame_buffers();  // as the program does
  const int frames = 16;
  const pipeline::BenchScene scene = pipeline::load_bench_scene("night-city", 960, 540, frames);
  ASSERT_EQ(scene.frames.size(), size_t(frames));
  for (const char* preset : {"fast", "balanced", "reference"}) {
    const SteadyState s = steady_state(scene, preset);
    const test::AllocationCount& c = s.malloc;
    const double per_frame = double(c.calls) / (frames - kWarmUp);
    std::printf("%s: %lld allocations in %d frames (%.1f a frame, %lld bytes in all, largest %zu, %lld large), "
                "%lu blocks mapped by the pool\n",
                preset, c.calls, frames - kWarmUp, per_frame, c.bytes, c.largest, c.large_calls, s.mapped_blocks);
    EXPECT_EQ(c.large_calls, 0) << preset << ": largest " << c.largest << " bytes";
    EXPECT_EQ(s.mapped_blocks, 0ul) << preset;
  }
}

}  // namespace
}  // namespace eyestream
