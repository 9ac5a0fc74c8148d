#include "io/video_writer.hpp"

#include "io/ycbcr.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/imgutils.h>
#include <libavutil/mastering_display_metadata.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <opencv2/core.hpp>
#include <vector>

#include "io/av_error.hpp"
#include "io/error.hpp"
#include "io/staged_file.hpp"
#include "io/transfer_functions.hpp"

namespace eyestream::io {

struct VideoWriter::Impl {
  std::optional<StagedFile> file;  // none when writing to standard output
  std::string name;                 // for messages
  VideoOptions options;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  SwsContext* sws = nullptr;
  AVFrame* yuv = nullptr;
  AVPacket* packet = nullptr;
  AVRational rate{};
  int width = 0, height = 0;  // encoded (even) size
  std::int64_t last_pts = -1;
  std::int64_t frames = 0;
  // HDR10: the content light level measured from the frames (CTA-861.3):
  // MaxCLL the brightest pixel's largest component, MaxFALL the largest
  // frame mean of that component, in cd/m^2.
  std::vector<float> pq_light;  // 16-bit PQ code -> cd/m^2
  double max_cll = 0, max_fall = 0;

  Impl(const std::string& path, const VideoOptions& o) : name(path == "-" ? "standard output" : path), options(o) {
    if (path != "-") file.emplace(path);
  }

  ~Impl() {
    sws_freeContext(sws);
    av_frame_free(&yuv);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    if (format) {
      if (format->pb) avio_closep(&format->pb);
      avformat_free_context(format);
    }
  }

  [[noreturn]] void fail(const std::string& what, int code) const {
    if (code == AVERROR(EBADF) && !file) throw OutputError(name + " is closed: nowhere to write the video");
    if (code == AVERROR(EPIPE))  // `eyestream run -o - | head`: not a disk problem
      throw OutputError(name + ": the program reading it closed the pipe (" + std::to_string(frames) +
                        " frames had gone to the encoder)");
    throw OutputError(name + ": " + what + ": " + av_error_text(code));
  }

  void open(int frame_width, int frame_height) {
    width = frame_width + (frame_width & 1);
    height = frame_height + (frame_height & 1);
    rate = av_d2q(options.frames_per_second, 1 << 20);
    const std::string target = file ? file->temp_path().string() : "pipe:1";
    const std::string ext = file ? file->final_path().extension().string() : "." + options.stream_format;
    const bool mkv = ext == ".mkv" || ext == ".MKV";
    int rc = avformat_alloc_output_context2(&format, nullptr, mkv ? "matroska" : "mp4", target.c_str());
    if (rc < 0) fail("cannot set up the container", rc);
    format->flags |= AVFMT_FLAG_BITEXACT;  // no random Matroska UIDs: same inputs, same bytes
    const char* encoder_name = options.codec == "hevc" ? "libx265" : "libx264";
    const AVCodec* encoder = avcodec_find_encoder_by_name(encoder_name);
    if (!encoder)
      throw OutputError(name + ": this FFmpeg build has no " + encoder_name + " encoder");
    stream = avformat_new_stream(format, nullptr);
    codec = avcodec_alloc_context3(encoder);
    if (!stream || !codec) throw OutputError(name + ": out of memory");
    codec->width = width;
    codec->height = height;
    codec->pix_fmt = pixel_format();
    codec->time_base = av_inv_q(rate);
    codec->framerate = rate;
    codec->gop_size = options.keyint;
    if (options.b_frames >= 0) codec->max_b_frames = options.b_frames;  // after the preset (x264 and x265)
    tag(codec->color_primaries, codec->color_trc, codec->colorspace);
    codec->color_range = AVCOL_RANGE_MPEG;
    codec->thread_count = options.encoder_threads;
    if (format->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* opts = nullptr;
    av_dict_set(&opts, "crf", std::to_string(options.crf).c_str(), 0);
    av_dict_set(&opts, "preset", options.preset.c_str(), 0);
    if (options.codec == "hevc") av_dict_set(&opts, "x265-params", x265_params().c_str(), 0);
    if (options.codec != "hevc" && options.lookahead >= 0)
      av_dict_set(&opts, "rc-lookahead", std::to_string(options.lookahead).c_str(), 0);
    // x264's AVX-512 kernels (mbtree) read past their buffers, so its output
    // depended on what lay beside them (the thread count, the timing): on a
    // CPU with AVX-512, x264 is held to its AVX2 kernels, with which the
    // bytes depend on the frames alone (tests/end_to_end_test.cpp).
    std::string x264;
#if defined(__x86_64__) || defined(__i386__)
    if (options.codec != "hevc" && __builtin_cpu_supports("avx512f")) x264 = "asm=avx2,fma3,bmi2,lzcnt";
#endif
    // Sliced threads: each thread codes a slice of every frame, so x264
    // holds one frame in work instead of one per thread.
    if (options.codec != "hevc" && options.sliced_threads) x264 += std::string(x264.empty() ? "" : ":") + "sliced-threads=1";
    if (!x264.empty()) av_dict_set(&opts, "x264-params", x264.c_str(), 0);
    rc = avcodec_open2(codec, encoder, &opts);
    av_dict_free(&opts);
    if (rc < 0) fail(std::string("cannot open the ") + encoder_name + " encoder", rc);
    rc = avcodec_parameters_from_context(stream->codecpar, codec);
    if (rc < 0) fail("cannot set stream parameters", rc);
    // HEVC in MP4 as 'hvc1' (parameter sets in the sample entry): Apple's
    // players refuse the default 'hev1'.
    if (!mkv && options.codec == "hevc") stream->codecpar->codec_tag = MKTAG('h', 'v', 'c', '1');
    stream->time_base = codec->time_base;
    stream->avg_frame_rate = rate;
    rc = avio_open(&format->pb, target.c_str(), AVIO_FLAG_WRITE);
    if (rc < 0) fail("cannot open for writing", rc);
    if (options.hdr10) add_hdr10_side_data();
    AVDictionary* muxer = nullptr;
    if (!file && !mkv) av_dict_set(&muxer, "movflags", "frag_keyframe+empty_moov", 0);  // MP4 on a pipe
    // An MP4 file plays while it downloads: its index goes to the front.
    if (file && !mkv) av_dict_set(&muxer, "movflags", "faststart", 0);
    rc = avformat_write_header(format, &muxer);
    av_dict_free(&muxer);
    if (rc < 0) fail("cannot write the container header", rc);

    if (options.bit_depth <= 8) {  // 8-bit RGB to Y'CbCr by swscale; deeper by ycbcr.hpp
      sws = sws_getContext(width, height, AV_PIX_FMT_RGB24, width, height, pixel_format(),
                           SWS_BICUBIC | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
      if (!sws) throw OutputError(name + ": cannot set up colour conversion");
      const int* matrix = sws_getCoefficients(SWS_CS_ITU709);
      sws_setColorspaceDetails(sws, matrix, 1, matrix, 0, 0, 1 << 16, 1 << 16);
    }
    yuv = av_frame_alloc();
    packet = av_packet_alloc();
    if (!yuv || !packet) throw OutputError(name + ": out of memory");
    yuv->format = pixel_format();
    yuv->width = width;
    yuv->height = height;
    tag(yuv->color_primaries, yuv->color_trc, yuv->colorspace);
    yuv->color_range = AVCOL_RANGE_MPEG;
    rc = av_frame_get_buffer(yuv, 0);
    if (rc < 0) fail("cannot allocate a frame", rc);
  }

  AVPixelFormat pixel_format() const { return options.bit_depth > 8 ? AV_PIX_FMT_YUV420P10LE : AV_PIX_FMT_YUV420P; }

  void tag(AVColorPrimaries& primaries, AVColorTransferCharacteristic& transfer, AVColorSpace& matrix) const {
    const bool wide = options.hdr10 || options.hlg;
    primaries = wide ? AVCOL_PRI_BT2020 : AVCOL_PRI_BT709;
    transfer = options.hdr10 ? AVCOL_TRC_SMPTE2084 : options.hlg ? AVCOL_TRC_ARIB_STD_B67 : AVCOL_TRC_BT709;
    matrix = wide ? AVCOL_SPC_BT2020_NCL : AVCOL_SPC_BT709;
  }

  // x265: quiet, fixed threading (output bytes depend on it), and for
  // HDR10 the mastering display (BT.2020 primaries and D65 in 0.00002
  // units, luminance in 0.0001 cd/m^2) in the SEI. The content light level
  // is known only after the last frame, so it goes to the container alone.
  std::string x265_params() const {
    std::string p = "log-level=error:frame-threads=1:pools=" + std::to_string(options.encoder_threads);
    if (options.hdr10) {
      const long peak = std::lround(options.hdr10_peak_cd_m2 * 10000);
      p += ":hdr10=1:repeat-headers=1:master-display=G(8500,39850)B(6550,2300)R(35400,14600)WP(15635,16450)L(" +
           std::to_string(peak) + ",1)";
    }
    return p;
  }

  // The same metadata for the container, with a content light level of 0
  // (unknown) until close() measures it.
  void add_hdr10_side_data() {
    size_t size = 0;
    AVMasteringDisplayMetadata* m = av_mastering_display_metadata_alloc();
    const double xy[4][2] = {{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}, {0.3127, 0.3290}};  // R, G, B, white
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 2; ++j) m->display_primaries[i][j] = av_d2q(xy[i][j], 50000);
    m->white_point[0] = av_d2q(xy[3][0], 50000);
    m->white_point[1] = av_d2q(xy[3][1], 50000);
    m->max_luminance = av_d2q(options.hdr10_peak_cd_m2, 10000);
    m->min_luminance = av_make_q(1, 10000);
    m->has_primaries = m->has_luminance = 1;
    av_stream_add_side_data(stream, AV_PKT_DATA_MASTERING_DISPLAY_METADATA, reinterpret_cast<uint8_t*>(m),
                            sizeof(*m));
    AVContentLightMetadata* cll = av_content_light_metadata_alloc(&size);
    cll->MaxCLL = cll->MaxFALL = 0;
    av_stream_add_side_data(stream, AV_PKT_DATA_CONTENT_LIGHT_LEVEL, reinterpret_cast<uint8_t*>(cll), size);
  }

  void measure_light(const cv::Mat& code) {
    if (pq_light.empty()) {
      pq_light.resize(65536);
      for (int i = 0; i < 65536; ++i) pq_light[i] = float(pq_to_luminance(i / 65535.0));
    }
    std::uint16_t brightest = 0;
    double sum = 0;
    for (int y = 0; y < code.rows; ++y) {
      const std::uint16_t* p = code.ptr<std::uint16_t>(y);
      double row = 0;
      for (int x = 0; x < code.cols; ++x, p += 3) {
        const std::uint16_t m = std::max({p[0], p[1], p[2]});
        brightest = std::max(brightest, m);
        row += pq_light[m];
      }
      sum += row;
    }
    max_cll = std::max(max_cll, double(pq_light[brightest]));
    max_fall = std::max(max_fall, sum / double(code.total()));
  }

  // The measured content light level into the container's side data, which
  // the MP4 muxer writes with its index at the end (MKV's track header is
  // written first and keeps 0, "unknown").
  void store_light_level() {
    size_t size = 0;
    uint8_t* data = av_stream_get_side_data(stream, AV_PKT_DATA_CONTENT_LIGHT_LEVEL, &size);
    if (!data || size < sizeof(AVContentLightMetadata)) return;
    auto* cll = reinterpret_cast<AVContentLightMetadata*>(data);
    cll->MaxCLL = unsigned(std::min(65535L, std::lround(max_cll)));
    cll->MaxFALL = unsigned(std::min(65535L, std::lround(max_fall)));
  }

  void drain() {
    for (;;) {
      int rc = avcodec_receive_packet(codec, packet);
      if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return;
      if (rc < 0) fail("encoding failed", rc);
      if (packet->duration == 0) packet->duration = 1;
      // x265 leaves a lone frame's timestamps unset: it is the last frame sent.
      if (packet->pts == AV_NOPTS_VALUE) packet->pts = packet->dts != AV_NOPTS_VALUE ? packet->dts : last_pts;
      if (packet->dts == AV_NOPTS_VALUE) packet->dts = packet->pts;
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      rc = av_interleaved_write_frame(format, packet);
      if (rc < 0) fail("write failed (disk full?)", rc);
    }
  }

  void encode(const cv::Mat& code, double time_s) {
    cv::Mat padded = code;
    if (code.cols != width || code.rows != height)
      cv::copyMakeBorder(code, padded, 0, height - code.rows, 0, width - code.cols, cv::BORDER_REPLICATE);
    int rc = av_frame_make_writable(yuv);
    if (rc < 0) fail("cannot write a frame", rc);
    // A buffer made writable may be fresh, its row padding uninitialised,
    // and x264's SIMD reads past the row's end: cleared, so the encoded
    // bytes depend on the frame alone, not on what the heap held before.
    for (AVBufferRef* buf : yuv->buf)
      if (buf) std::memset(buf->data, 0, buf->size);
    if (options.hdr10) measure_light(code);
    if (options.bit_depth > 8) {  // the standard's arithmetic (ycbcr.hpp), not swscale's 16-bit path
      rgb_to_ycbcr420_10(code, yuv->colorspace, *yuv);
    } else {
      const uint8_t* src[1] = {padded.ptr<uint8_t>()};
      const int src_stride[1] = {int(padded.step[0])};
      sws_scale(sws, src, src_stride, 0, height, yuv->data, yuv->linesize);
    }
    std::int64_t pts = std::llround(time_s * av_q2d(rate));
    if (pts <= last_pts) pts = last_pts + 1;
    last_pts = pts;
    yuv->pts = pts;
    rc = avcodec_send_frame(codec, yuv);
    if (rc < 0) fail("encoding failed", rc);
    ++frames;
    drain();
  }

  void close() {
    if (!format) throw OutputError(name + ": no frame was written");
    int rc = avcodec_send_frame(codec, nullptr);
    if (rc < 0) fail("encoding failed", rc);
    drain();
    if (options.hdr10) store_light_level();
    rc = av_write_trailer(format);
    if (rc < 0) fail("cannot finalise the video file", rc);
    rc = avio_closep(&format->pb);
    if (rc < 0) fail("cannot close (disk full?)", rc);
    if (file) file->commit();
  }
};

namespace {

VideoOptions resolved(VideoOptions o) {
  if (o.hdr10 || o.hlg) o.bit_depth = 10;
  if (o.hdr10 && o.hlg) throw UsageError("HDR10 and HLG: choose one");
  if (o.codec == "auto") o.codec = o.bit_depth > 8 ? "hevc" : "h264";
  if (!(o.frames_per_second > 0)) throw UsageError("--fps: frame rate must be positive");
  if (o.codec != "h264" && o.codec != "hevc") throw UsageError("--codec: auto, h264 or hevc");
  if (o.bit_depth != 8 && o.bit_depth != 10) throw UsageError("--bit-depth: 8 or 10");
  if (o.bit_depth == 10 && o.codec != "hevc") throw UsageError("--bit-depth 10 and --hdr10 need --codec hevc");
  return o;
}

}  // namespace

VideoWriter::VideoWriter(const std::string& path, const VideoOptions& options)
    : options_(resolved(options)), impl_(std::make_unique<Impl>(path, options_)) {}

SinkNeeds VideoWriter::needs_for(const VideoOptions& options) {
  if (options.hdr10) return SinkNeeds::kPq16;
  return options.bit_depth > 8 ? SinkNeeds::kCode16 : SinkNeeds::kCode8;
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::write(const DisplayFrame& frame) {
  CV_Assert(frame.code.type() == (impl_->options.bit_depth > 8 ? CV_16UC3 : CV_8UC3));
  if (!impl_->format) impl_->open(frame.code.cols, frame.code.rows);
  impl_->encode(frame.code, frame.time_s);
}

void VideoWriter::finish() { impl_->close(); }

}  // namespace eyestream::io
