// HDR video luminance against an independent oracle, both ways. The PQ
// formula (SMPTE ST 2084) and the limited-range Y'CbCr code values
// (BT.2100: Y = 64 + 876 E', 10 bits) are written out here, not taken from
// eyestream:
// - reading: a lossless FFV1 clip made here with libavcodec, grey patches
//   whose code values are computed from the formula, tagged PQ (or HLG),
//   BT.2020, limited range, must read back as the luminance the codes mean;
// - writing: eyestream's HDR10 output, decoded here with libavcodec (no
//   eyestream code), must hold the codes of the luminance it meant.
// (A swscale 16-bit packed RGB path, scaled to 0xFF00 instead of 0xFFFF,
// once read PQ 1.5-3 % too dark and wrote HDR10 1.9 % too bright; a round
// trip through eyestream's own writer and reader hid both.)
#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <cmath>
#include <cstring>

#include "io/video_source.hpp"
#include "io/video_writer.hpp"
#include "pipeline/preview/hdr10_encoding.hpp"
#include "tests/decoded_video.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

constexpr int kW = 64, kH = 32;

// SMPTE ST 2084, written out: E' in [0, 1] to cd/m^2 and back.
double pq_eotf(double e) {
  const double m1 = 2610.0 / 16384, m2 = 2523.0 / 4096 * 128, c1 = 3424.0 / 4096, c2 = 2413.0 / 4096 * 32,
               c3 = 2392.0 / 4096 * 32;
  const double p = std::pow(e, 1.0 / m2);
  return 10000.0 * std::pow(std::max(p - c1, 0.0) / (c2 - c3 * p), 1.0 / m1);
}
double pq_inverse(double l) {
  const double m1 = 2610.0 / 16384, m2 = 2523.0 / 4096 * 128, c1 = 3424.0 / 4096, c2 = 2413.0 / 4096 * 32,
               c3 = 2392.0 / 4096 * 32;
  const double y = std::pow(l / 10000.0, m1);
  return std::pow((c1 + c2 * y) / (1 + c3 * y), m2);
}
int luma_code(double l) { return int(std::lround(64 + 876 * pq_inverse(l))); }
double code_luminance(double y) { return pq_eotf((y - 64) / 876.0); }

// HLG (BT.2100), written out: scene light E in [0, 1] to E'.
double hlg_oetf(double e) {
  const double a = 0.17883277, b = 1 - 4 * a, c = 0.5 - a * std::log(4 * a);
  return e <= 1.0 / 12 ? std::sqrt(3 * e) : a * std::log(12 * e - b) + c;
}

// A lossless clip of one frame: a grey patch per 10-bit luma code, side by side.
bool write_clip(const std::string& path, const std::vector<int>& codes, AVColorTransferCharacteristic transfer) {
  AVFormatContext* out = nullptr;
  if (avformat_alloc_output_context2(&out, nullptr, "matroska", path.c_str()) < 0) return false;
  const AVCodec* ffv1 = avcodec_find_encoder(AV_CODEC_ID_FFV1);
  AVCodecContext* c = avcodec_alloc_context3(ffv1);
  c->width = kW, c->height = kH, c->pix_fmt = AV_PIX_FMT_YUV420P10LE, c->time_base = {1, 30};
  c->color_primaries = AVCOL_PRI_BT2020, c->color_trc = transfer, c->colorspace = AVCOL_SPC_BT2020_NCL;
  c->color_range = AVCOL_RANGE_MPEG;
  bool ok = avcodec_open2(c, ffv1, nullptr) >= 0;
  AVStream* stream = avformat_new_stream(out, nullptr);
  ok = ok && avcodec_parameters_from_context(stream->codecpar, c) >= 0;
  stream->time_base = {1, 30};
  ok = ok && avio_open(&out->pb, path.c_str(), AVIO_FLAG_WRITE) >= 0 && avformat_write_header(out, nullptr) >= 0;
  AVFrame* f = av_frame_alloc();
  f->format = c->pix_fmt, f->width = kW, f->height = kH;
  ok = ok && av_frame_get_buffer(f, 0) >= 0;
  const int patch = kW / int(codes.size());
  for (int y = 0; ok && y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      reinterpret_cast<std::uint16_t*>(f->data[0] + y * f->linesize[0])[x] =
          std::uint16_t(codes[size_t(std::min(x / patch, int(codes.size()) - 1))]);
      if (y < kH / 2 && x < kW / 2)
        for (int p : {1, 2}) reinterpret_cast<std::uint16_t*>(f->data[p] + y * f->linesize[p])[x] = 512;
    }
  f->pts = 0;
  AVPacket* packet = av_packet_alloc();
  ok = ok && avcodec_send_frame(c, f) >= 0 && avcodec_send_frame(c, nullptr) >= 0;
  while (ok && avcodec_receive_packet(c, packet) >= 0) {
    av_packet_rescale_ts(packet, c->time_base, stream->time_base);
    packet->stream_index = 0;
    ok = av_write_frame(out, packet) >= 0;
    av_packet_unref(packet);
  }
  ok = ok && av_write_trailer(out) >= 0;
  av_packet_free(&packet);
  av_frame_free(&f);
  avcodec_free_context(&c);
  avio_closep(&out->pb);
  avformat_free_context(out);
  return ok;
}

// The first frame's luma plane of a video, decoded here (10-bit codes).
cv::Mat decode_luma(const std::string& path) {
  cv::Mat luma;
  test::for_each_decoded_frame(path, [&](const AVFrame& f) {
    if (f.format == AV_PIX_FMT_YUV420P10LE) {
      luma.create(f.height, f.width, CV_16U);
      for (int y = 0; y < f.height; ++y) std::memcpy(luma.ptr(y), f.data[0] + y * f.linesize[0], size_t(f.width) * 2);
    }
    return false;  // the first frame only
  });
  return luma;
}

double luminance(const cv::Vec3f& p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

TEST(HdrVideoOracle, PqCodesReadAsTheLuminanceTheyMean) {
  test::ScratchDir dir;
  const std::vector<double> levels = {5.0, 100.0, 1000.0};
  ASSERT_TRUE(write_clip(dir / "pq.mkv", {luma_code(5.0), luma_code(100.0), luma_code(1000.0)}, AVCOL_TRC_SMPTE2084));
  io::VideoSource source(dir / "pq.mkv", {});
  const auto frame = source.next();
  ASSERT_TRUE(frame);
  for (size_t i = 0; i < levels.size(); ++i) {
    const int x = int(i) * (kW / 3) + kW / 6;
    const double want = code_luminance(luma_code(levels[i]));  // the code's own value
    const double got = luminance(frame->rgb.at<cv::Vec3f>(kH / 2, x));
    EXPECT_NEAR(got / want, 1.0, 0.002) << levels[i] << " cd/m^2 (code " << luma_code(levels[i]) << ")";
    EXPECT_NEAR(got / levels[i], 1.0, 0.007) << "within the 10-bit quantisation";
  }
}

TEST(HdrVideoOracle, HlgNominalPeakAndHalfSignalReadAsBt2100Says) {
  // Grey at scene light E shows Lw E^gamma (BT.2100 OOTF; gamma 1.2 at
  // Lw = 1000): E = 1 (code 940) is the nominal peak, E = 0.26 a mid grey.
  test::ScratchDir dir;
  const double mid = 0.26;
  const int mid_code = int(std::lround(64 + 876 * hlg_oetf(mid)));
  ASSERT_TRUE(write_clip(dir / "hlg.mkv", {940, mid_code}, AVCOL_TRC_ARIB_STD_B67));
  io::VideoSourceOptions o;
  o.peak_cd_m2 = 1000;
  io::VideoSource source(dir / "hlg.mkv", o);
  const auto frame = source.next();
  ASSERT_TRUE(frame);
  EXPECT_NEAR(luminance(frame->rgb.at<cv::Vec3f>(kH / 2, kW / 4)) / 1000.0, 1.0, 0.007) << "nominal peak";
  // The mid grey against the code's own scene light, inverted here by bisection.
  double lo = 0, hi = 1;
  for (int i = 0; i < 60; ++i) ((64 + 876 * hlg_oetf(0.5 * (lo + hi)) < mid_code) ? lo : hi) = 0.5 * (lo + hi);
  const double want = 1000 * std::pow(lo, 1.2);
  EXPECT_NEAR(luminance(frame->rgb.at<cv::Vec3f>(kH / 2, 3 * kW / 4)) / want, 1.0, 0.002) << want << " cd/m^2";
}

TEST(HdrVideoOracle, Hdr10OutputHoldsTheCodesOfTheLuminanceItMeant) {
  test::ScratchDir dir;
  const double peak = 1000.0;
  for (double l : {5.0, 100.0, 1000.0}) {
    io::VideoOptions o;
    o.hdr10 = true;
    o.crf = 0;
    o.frames_per_second = 30;
    cv::Mat code;
    pipeline::encode_hdr10(cv::Mat(kH, kW, CV_32FC3, cv::Scalar::all(l / peak)), peak, code);
    const std::string path = dir / ("out" + std::to_string(int(l)) + ".mkv");
    {
      io::VideoWriter writer(path, o);
      io::DisplayFrame f;
      f.code = code;
      writer.write(f);
      writer.finish();
    }
    const cv::Mat luma = decode_luma(path);
    ASSERT_FALSE(luma.empty()) << path;
    const double y = cv::mean(luma)[0];
    EXPECT_NEAR(y, luma_code(l), 0.5) << l << " cd/m^2: luma code";
    EXPECT_NEAR(code_luminance(y) / l, 1.0, 0.007) << l << " cd/m^2";
  }
}

// `compare` decodes PQ videos to light: two lossless clips whose codes mean
// 100 and 150 cd/m^2 differ by 50 cd/m^2 over the 203 cd/m^2 reference
// white (BT.2408), the codes' own values computed here. An HDR clip against
// an SDR one is refused as a mismatch.
TEST(HdrVideoOracle, CompareDecodesPqVideosToLight) {
  test::ScratchDir dir;
  const int a = luma_code(100.0), b = luma_code(150.0);
  ASSERT_TRUE(write_clip(dir / "a.mkv", {a}, AVCOL_TRC_SMPTE2084));
  ASSERT_TRUE(write_clip(dir / "b.mkv", {b}, AVCOL_TRC_SMPTE2084));
  ASSERT_TRUE(write_clip(dir / "sdr.mkv", {a}, AVCOL_TRC_BT709));
  const auto r = test::run_eyestream("compare " + (dir / "a.mkv") + " " + (dir / "b.mkv") + " --metric max --warn 0 --fail 0.1 --json " +
                                     (dir / "r.json"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  const std::string json = test::read_bytes(dir / "r.json");
  const size_t at = json.find("\"max_abs\"");
  ASSERT_NE(at, std::string::npos) << json;
  const double max_abs = std::stod(json.substr(json.find(':', at) + 1));
  const double want = (code_luminance(b) - code_luminance(a)) / 203.0;
  EXPECT_NEAR(max_abs / want, 1.0, 0.002) << r.output;
  const auto same = test::run_eyestream("compare " + (dir / "a.mkv") + " " + (dir / "a.mkv"));
  EXPECT_EQ(same.exit_code, 0) << same.output;
  const auto mixed = test::run_eyestream("compare " + (dir / "a.mkv") + " " + (dir / "sdr.mkv"));
  EXPECT_EQ(mixed.exit_code, 2) << mixed.output;
  EXPECT_NE(mixed.output.find("PQ/HLG video (light)"), std::string::npos) << mixed.output;
}

}  // namespace
}  // namespace eyestream
