#include "io/video_reader.hpp"

#include "io/ycbcr.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <cmath>

#include "io/av_error.hpp"
#include "io/error.hpp"

namespace eyestream::io {

namespace {

std::string name_or_unknown(const char* s) { return s ? s : "unknown"; }


// libswscale's YUV->RGB coefficients for the stream's matrix.
int sws_matrix(AVColorSpace space) {
  switch (space) {
    case AVCOL_SPC_BT2020_NCL:
    case AVCOL_SPC_BT2020_CL: return SWS_CS_BT2020;
    case AVCOL_SPC_BT470BG:
    case AVCOL_SPC_SMPTE170M: return SWS_CS_ITU601;
    default: return SWS_CS_ITU709;
  }
}

}  // namespace

struct VideoReader::Impl {
  std::string path;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVPacket* packet = nullptr;
  AVFrame* frame = nullptr;
  SwsContext* sws = nullptr;
  int stream = -1;
  VideoColour colour;
  std::int64_t decoded = 0;
  int width = 0, height = 0;  // the stream's size when opened
  std::optional<std::int64_t> first_pts;
  bool draining = false, done = false;

  ~Impl() {
    sws_freeContext(sws);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
  }

  [[noreturn]] void fail(const std::string& what) const { throw InputError(path + ": " + what); }

  void open() {
    if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) fail("cannot open as a video");
    if (avformat_find_stream_info(format, nullptr) < 0) fail("cannot read the stream information");
    const AVCodec* decoder = nullptr;
    stream = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
    if (stream < 0 || !decoder) fail("no decodable video stream");
    const AVCodecParameters* par = format->streams[stream]->codecpar;
    codec = avcodec_alloc_context3(decoder);
    if (!codec || avcodec_parameters_to_context(codec, par) < 0) fail("cannot set up the decoder");
    codec->thread_count = 1;  // decoded pictures do not depend on it; one thread keeps memory flat
    if (avcodec_open2(codec, decoder, nullptr) < 0) fail("cannot open the decoder");
    width = codec->width;
    height = codec->height;
    packet = av_packet_alloc();
    frame = av_frame_alloc();
    colour.transfer = name_or_unknown(av_color_transfer_name(par->color_trc));
    colour.primaries = name_or_unknown(av_color_primaries_name(par->color_primaries));
    colour.matrix = name_or_unknown(av_color_space_name(par->color_space));
    colour.full_range = par->color_range == AVCOL_RANGE_JPEG;
    const AVPixFmtDescriptor* desc = av_pix_fmt_desc_get(AVPixelFormat(par->format));
    colour.bit_depth = desc ? desc->comp[0].depth : 8;
  }

  // Receives one decoded picture into `frame`; false at the end.
  bool receive() {
    while (!done) {
      const int rc = avcodec_receive_frame(codec, frame);
      if (rc == 0) return true;
      if (rc == AVERROR_EOF) {
        done = true;
        break;
      }
      if (rc != AVERROR(EAGAIN)) fail("frame " + std::to_string(decoded) + ": cannot decode");
      if (draining) {
        done = true;
        break;
      }
      const int read = av_read_frame(format, packet);
      if (read < 0) {
        draining = true;
        avcodec_send_packet(codec, nullptr);
        continue;
      }
      if (packet->stream_index == stream) {
        const int sent = avcodec_send_packet(codec, packet);
        if (sent < 0 && sent != AVERROR(EAGAIN))
          fail("frame " + std::to_string(decoded) + ": corrupt packet (" + av_error_text(sent) + ")");
      }
      av_packet_unref(packet);
    }
    return false;
  }

  // Converts the picture just received, frame `decoded - 1`.
  cv::Mat to_rgb() {
    const std::int64_t index = decoded - 1;
    if (width <= 0 || height <= 0) width = frame->width, height = frame->height;
    if (frame->width != width || frame->height != height)
      fail("frame " + std::to_string(index) + " is " + std::to_string(frame->width) + "x" +
           std::to_string(frame->height) + ", the video began at " + std::to_string(width) + "x" +
           std::to_string(height) + " (a video whose size changes is not supported)");
    const AVPixelFormat src = AVPixelFormat(frame->format);
    const AVColorSpace matrix =
        frame->colorspace != AVCOL_SPC_UNSPECIFIED ? frame->colorspace : format->streams[stream]->codecpar->color_space;
    const bool full = frame->color_range == AVCOL_RANGE_JPEG || colour.full_range;
    // Planar Y'CbCr (what video decoders give): the standard's arithmetic.
    if (is_planar_ycbcr(src)) return ycbcr_to_rgb(*frame, matrix, full);
    sws = sws_getCachedContext(sws, frame->width, frame->height, src, frame->width, frame->height,
                               AV_PIX_FMT_RGB48LE, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr,
                               nullptr, nullptr);
    if (!sws) fail("frame " + std::to_string(index) + ": cannot convert its pixel format");
    // Anything else (RGB and packed formats) through swscale.
    sws_setColorspaceDetails(sws, sws_getCoefficients(sws_matrix(matrix)), full, sws_getCoefficients(SWS_CS_DEFAULT),
                             1, 0, 1 << 16, 1 << 16);
    cv::Mat rgb48(frame->height, frame->width, CV_16UC3);
    uint8_t* dst[1] = {rgb48.data};
    const int dst_stride[1] = {int(rgb48.step)};
    sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, dst_stride);
    cv::Mat out;
    rgb48.convertTo(out, CV_32FC3, 1.0 / 65535.0);
    return out;
  }
};

VideoReader::VideoReader(const std::string& path) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  impl_->open();
}

VideoReader::~VideoReader() = default;

int VideoReader::width() const { return impl_->width; }
int VideoReader::height() const { return impl_->height; }
double VideoReader::frames_per_second() const {
  const AVRational r = impl_->format->streams[impl_->stream]->avg_frame_rate;
  return r.den ? av_q2d(r) : 0.0;
}
std::int64_t VideoReader::frame_count() const {
  const std::int64_t n = impl_->format->streams[impl_->stream]->nb_frames;
  return n > 0 ? n : -1;
}
double VideoReader::duration_s() const {
  const std::int64_t d = impl_->format->duration;
  return d > 0 ? double(d) / AV_TIME_BASE : -1.0;
}

const VideoColour& VideoReader::colour() const { return impl_->colour; }
const std::string& VideoReader::path() const { return impl_->path; }

std::optional<VideoFrame> VideoReader::next() {
  if (!impl_->receive()) return std::nullopt;
  VideoFrame f;
  f.index = impl_->decoded++;
  const std::int64_t pts = impl_->frame->best_effort_timestamp;
  if (pts != AV_NOPTS_VALUE) {
    if (!impl_->first_pts) impl_->first_pts = pts;
    f.time_s = double(pts - *impl_->first_pts) * av_q2d(impl_->format->streams[impl_->stream]->time_base);
  } else {
    const double fps = frames_per_second();
    f.time_s = fps > 0 ? f.index / fps : 0.0;
  }
  f.rgb = impl_->to_rgb();
  av_frame_unref(impl_->frame);
  return f;
}

}  // namespace eyestream::io
