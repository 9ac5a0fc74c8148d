// Videos that do not hold what they claim. A video whose picture size
// changes mid-stream (a new sequence header) is
// refused naming the frame, exit 3, not an internal error. The fixture is
// made here with libavcodec: a raw H.264 stream of five 32x24 frames, then
// five 48x32 ones.
#include <gtest/gtest.h>

#include <array>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <algorithm>
#include <cstring>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "tests/test_support.hpp"

namespace eyestream {
namespace {

bool write_two_size_stream(const std::string& path) {
  AVFormatContext* out = nullptr;
  if (avformat_alloc_output_context2(&out, nullptr, "h264", path.c_str()) < 0) return false;
  AVStream* stream = avformat_new_stream(out, nullptr);
  stream->codecpar->codec_type = AVMEDIA_TYPE_VIDEO;
  stream->codecpar->codec_id = AV_CODEC_ID_H264;
  stream->codecpar->width = 32;
  stream->codecpar->height = 24;
  stream->time_base = {1, 30};
  bool ok = avio_open(&out->pb, path.c_str(), AVIO_FLAG_WRITE) >= 0 && avformat_write_header(out, nullptr) >= 0;
  const AVCodec* x264 = avcodec_find_encoder_by_name("libx264");
  AVPacket* packet = av_packet_alloc();
  std::int64_t pts = 0;
  for (const std::array<int, 2>& size : {std::array<int, 2>{32, 24}, std::array<int, 2>{48, 32}}) {
    AVCodecContext* c = avcodec_alloc_context3(x264);
    c->width = size[0];
    c->height = size[1];
    c->pix_fmt = AV_PIX_FMT_YUV420P;
    c->time_base = {1, 30};
    c->thread_count = 1;
    ok = ok && avcodec_open2(c, x264, nullptr) >= 0;
    AVFrame* frame = av_frame_alloc();
    frame->format = c->pix_fmt;
    frame->width = c->width;
    frame->height = c->height;
    ok = ok && av_frame_get_buffer(frame, 0) >= 0;
    const auto drain = [&] {
      while (avcodec_receive_packet(c, packet) >= 0) {
        packet->stream_index = 0;
        ok = ok && av_write_frame(out, packet) >= 0;
        av_packet_unref(packet);
      }
    };
    for (int i = 0; ok && i < 5; ++i) {
      for (int p = 0; p < 3; ++p) std::memset(frame->data[p], 60 + 20 * i, size_t(frame->linesize[p]) * (p ? c->height / 2 : c->height));
      frame->pts = pts++;
      ok = avcodec_send_frame(c, frame) >= 0;
      drain();
    }
    avcodec_send_frame(c, nullptr);
    drain();
    av_frame_free(&frame);
    avcodec_free_context(&c);
  }
  av_packet_free(&packet);
  ok = ok && av_write_trailer(out) >= 0;
  avio_closep(&out->pb);
  avformat_free_context(out);
  return ok;
}

TEST(VideoStreamChecks, AVideoWhoseSizeChangesIsRefusedNamingTheFrame) {
  test::ScratchDir dir;
  ASSERT_TRUE(write_two_size_stream(dir / "two.h264"));
  std::ofstream(dir / "gaze.csv") << "t,x,y\n0,16,12\n";
  const auto r = test::run_eyestream("run -i " + (dir / "two.h264") + " -g " + (dir / "gaze.csv") + " -o " +
                                     (dir / "out.mp4") + " --video-transfer sdr --video-peak 100");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("two.h264: frame 5 is 48x32, the video began at 32x24"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.mp4"));
}

// An MKV whose container duration claims one frame more than it holds
// (its Segment Info Duration patched): said in a warning, not refused;
// two frames more: refused, as before.
TEST(VideoStreamChecks, AnMkvShortOfItsDurationIsSaidOrRefused) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample flash -o " + (dir / "s") + " --width 64 --height 48 --duration 0.3").exit_code, 0);
  ASSERT_EQ(test::run_eyestream("run -i " + (dir / "s/frames") + " -o " + (dir / "v.mkv") + " --bit-depth 10").exit_code, 0);
  const std::string bytes = test::read_bytes(dir / "v.mkv");
  const std::string id = "\x44\x89\x88";  // Duration, an 8-byte float in timecode units (1 ms)
  const size_t at = bytes.find(id);
  ASSERT_NE(at, std::string::npos);
  const auto with_extra = [&](double frames) {
    unsigned char be[8];
    std::memcpy(be, bytes.data() + at + 3, 8);
    std::uint64_t bits = 0;
    for (unsigned char b : be) bits = (bits << 8) | b;
    double ms;
    std::memcpy(&ms, &bits, 8);
    ms += frames * 1000.0 / 30.0;
    std::memcpy(&bits, &ms, 8);
    std::string patched = bytes;
    for (int i = 7; i >= 0; --i, bits >>= 8) patched[at + 3 + size_t(i)] = char(bits & 0xff);
    std::ofstream(dir / "p.mkv", std::ios::binary | std::ios::trunc) << patched;
    std::filesystem::remove(dir / "out.mp4");
    return test::run_eyestream("run -i " + (dir / "p.mkv") + " -o " + (dir / "out.mp4") +
                               " --video-transfer sdr --video-peak 100");
  };
  auto r = with_extra(1.0);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("eyestream: warning: " + (dir / "p.mkv") + ": the last frame ends at"), std::string::npos)
      << r.output;
  r = with_extra(2.0);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("p.mkv: ends after 9 frames"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace eyestream
