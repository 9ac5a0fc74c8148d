// B-frames in the video: --b-frames 0 gives none, -1 leaves the speed
// preset's (x264 veryfast makes them on moving content), and --quality
// balanced sets 0 (x264 holds fewer frames: docs/performance.md). The
// frames' types are read back by FFmpeg's decoder, not by the writer.
#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <opencv2/imgproc.hpp>

#include "io/video_writer.hpp"
#include "pipeline/settings/quality_presets.hpp"
#include "pipeline/settings/settings.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

// 30 frames of a bright square crossing a textured field, as `preset` with
// `b_frames` writes them.
void write_moving_clip(const std::string& path, const std::string& preset, int b_frames) {
  io::VideoOptions o;
  o.preset = preset;
  o.b_frames = b_frames;
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

// How many of a video's decoded frames are B-frames (-1 if it cannot be read).
int b_frames_in(const std::string& path) {
  AVFormatContext* in = nullptr;
  if (avformat_open_input(&in, path.c_str(), nullptr, nullptr) < 0) return -1;
  avformat_find_stream_info(in, nullptr);
  const int s = av_find_best_stream(in, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  const AVCodec* decoder = avcodec_find_decoder(in->streams[s]->codecpar->codec_id);
  AVCodecContext* c = avcodec_alloc_context3(decoder);
  avcodec_parameters_to_context(c, in->streams[s]->codecpar);
  avcodec_open2(c, decoder, nullptr);
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  int b = 0, frames = 0;
  const auto drain = [&] {
    while (avcodec_receive_frame(c, frame) >= 0) {
      ++frames;
      b += frame->pict_type == AV_PICTURE_TYPE_B;
    }
  };
  while (av_read_frame(in, packet) >= 0) {
    if (packet->stream_index == s) avcodec_send_packet(c, packet);
    av_packet_unref(packet);
    drain();
  }
  avcodec_send_packet(c, nullptr);
  drain();
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&c);
  avformat_close_input(&in);
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

}  // namespace
}  // namespace eyestream
