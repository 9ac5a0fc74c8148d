// The encoder settings the presets choose for memory. B-frames: --b-frames
// 0 gives none, -1 leaves the speed preset's (x264 veryfast makes them on
// moving content), and --quality balanced sets 0. Lookahead: --lookahead
// N makes x264 look N frames ahead, -1 leaves the speed preset's, and
// balanced sets 5. Sliced threads: --sliced-threads makes each x264 thread
// code a slice of every frame, and balanced sets it. All three hold fewer
// frames in x264 (docs/performance.md).
// The frames' types are read back by FFmpeg's decoder, and the lookahead
// from the settings x264 itself writes into the stream, not by the writer.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <opencv2/imgproc.hpp>

#include "io/video_writer.hpp"
#include "pipeline/settings/quality_presets.hpp"
#include "pipeline/settings/settings.hpp"
#include "tests/decoded_video.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

// 30 frames of a bright square crossing a textured field, as `preset` with
// `b_frames` writes them.
void write_moving_clip(const std::string& path, const std::string& preset, int b_frames, int lookahead = -1,
                       bool sliced_threads = false) {
  io::VideoOptions o;
  o.preset = preset;
  o.b_frames = b_frames;
  o.lookahead = lookahead;
  o.sliced_threads = sliced_threads;
  io::VideoWriter writer(path, o);
  cv::Mat field(128, 192, CV_8UC3);
  cv::randu(field, cv::Scalar::all(40), cv::Scalar::all(120));
  cv::GaussianBlur(field, field, cv::Size(0, 0), 2.0);
  for (int i = 0; i < 30; ++i) {
    io::DisplayFrame f;
    f.code = field.clone();
    cv::rectangle(f.code, cv::Rect(4 * i, 40, 24, 24), cv::Scalar(250, 200, 30), cv::FILLED);
    f.index = i;
    f.time_s = i / 30.0;
    writer.write(f);
  }
  writer.finish();
}

// How many of a video's decoded frames are B-frames (-1 unless all 30
// frames decode).
int b_frames_in(const std::string& path) {
  int b = 0;
  const int frames = test::for_each_decoded_frame(path, [&](const AVFrame& f) {
    b += f.pict_type == AV_PICTURE_TYPE_B;
    return true;
  });
  return frames == 30 ? b : -1;
}

TEST(VideoBFrames, ZeroGivesNoneAndThePresetsDefaultGivesSome) {
  test::ScratchDir dir;
  write_moving_clip(dir / "preset.mp4", "veryfast", -1);
  write_moving_clip(dir / "none.mp4", "veryfast", 0);
  EXPECT_GT(b_frames_in(dir / "preset.mp4"), 0) << "x264 veryfast's own B-frames (without them the test shows nothing)";
  EXPECT_EQ(b_frames_in(dir / "none.mp4"), 0);
}

TEST(VideoBFrames, BalancedSetsNoneAndTheOtherPresetsLeaveTheSpeedPresets) {
  for (const char* name : {"reference", "balanced", "fast"}) {
    pipeline::Settings s;
    pipeline::apply_quality_preset(name, s);
    EXPECT_EQ(s.sink.video.b_frames, std::string(name) == "balanced" ? 0 : -1) << name;
  }
}

// A setting x264 reports in the settings it writes into the stream (its
// SEI text, "... rc_lookahead=N ..."); -1 if there is none.
int reported(const std::string& path, const std::string& name) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string key = " " + name + "=";
  const size_t at = bytes.find(key);
  return at == std::string::npos ? -1 : std::atoi(bytes.c_str() + at + key.size());
}
int reported_lookahead(const std::string& path) { return reported(path, "rc_lookahead"); }

TEST(VideoLookahead, TheOptionSetsX264sAndMinusOneLeavesThePresets) {
  test::ScratchDir dir;
  write_moving_clip(dir / "preset.mp4", "veryfast", -1);
  write_moving_clip(dir / "five.mp4", "veryfast", -1, 5);
  EXPECT_EQ(reported_lookahead(dir / "preset.mp4"), 10) << "x264 veryfast's own";
  EXPECT_EQ(reported_lookahead(dir / "five.mp4"), 5);
  EXPECT_GE(b_frames_in(dir / "five.mp4"), 0) << "the stream still decodes whole";
}

TEST(VideoLookahead, BalancedSetsFiveAndTheOtherPresetsLeaveTheSpeedPresets) {
  for (const char* name : {"reference", "balanced", "fast"}) {
    pipeline::Settings s;
    pipeline::apply_quality_preset(name, s);
    EXPECT_EQ(s.sink.video.lookahead, std::string(name) == "balanced" ? 5 : -1) << name;
  }
}

TEST(VideoSlicedThreads, TheOptionSetsX264sAndBalancedAloneSetsIt) {
  test::ScratchDir dir;
  write_moving_clip(dir / "frames.mp4", "veryfast", 0, 5);
  write_moving_clip(dir / "slices.mp4", "veryfast", 0, 5, true);
  EXPECT_EQ(reported(dir / "frames.mp4", "sliced_threads"), 0);
  EXPECT_EQ(reported(dir / "slices.mp4", "sliced_threads"), 1);
  EXPECT_EQ(reported(dir / "slices.mp4", "threads"), 2) << "two threads, a slice each";
  EXPECT_EQ(b_frames_in(dir / "slices.mp4"), 0) << "the stream decodes whole";
  for (const char* name : {"reference", "balanced", "fast"}) {
    pipeline::Settings s;
    pipeline::apply_quality_preset(name, s);
    EXPECT_EQ(s.sink.video.sliced_threads, std::string(name) == "balanced") << name;
  }
}

}  // namespace
}  // namespace eyestream
