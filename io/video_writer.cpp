#include "io/video_writer.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <cmath>
#include <opencv2/core.hpp>

#include "io/error.hpp"
#include "io/staged_file.hpp"

namespace eyestream::io {

namespace {

std::string av_message(int code) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {0};
  av_strerror(code, buf, sizeof(buf));
  return buf;
}

}  // namespace

struct VideoWriter::Impl {
  StagedFile file;
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

  Impl(const std::string& path, const VideoOptions& o) : file(path), options(o) {}

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
    throw OutputError(file.final_path().string() + ": " + what + ": " + av_message(code));
  }

  void open(int frame_width, int frame_height) {
    width = frame_width + (frame_width & 1);
    height = frame_height + (frame_height & 1);
    rate = av_d2q(options.frames_per_second, 1 << 20);
    const std::string temp = file.temp_path().string();
    int rc = avformat_alloc_output_context2(&format, nullptr, "mp4", temp.c_str());
    if (rc < 0) fail("cannot set up MP4 output", rc);
    const AVCodec* encoder = avcodec_find_encoder_by_name("libx264");
    if (!encoder) throw OutputError(file.final_path().string() + ": this FFmpeg build has no libx264 encoder");
    stream = avformat_new_stream(format, nullptr);
    codec = avcodec_alloc_context3(encoder);
    if (!stream || !codec) throw OutputError(file.final_path().string() + ": out of memory");
    codec->width = width;
    codec->height = height;
    codec->pix_fmt = AV_PIX_FMT_YUV420P;
    codec->time_base = av_inv_q(rate);
    codec->framerate = rate;
    codec->color_primaries = AVCOL_PRI_BT709;
    codec->color_trc = AVCOL_TRC_BT709;
    codec->colorspace = AVCOL_SPC_BT709;
    codec->color_range = AVCOL_RANGE_MPEG;
    codec->thread_count = options.encoder_threads;
    if (format->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* opts = nullptr;
    av_dict_set(&opts, "crf", std::to_string(options.crf).c_str(), 0);
    av_dict_set(&opts, "preset", options.preset.c_str(), 0);
    rc = avcodec_open2(codec, encoder, &opts);
    av_dict_free(&opts);
    if (rc < 0) fail("cannot open the H.264 encoder", rc);
    rc = avcodec_parameters_from_context(stream->codecpar, codec);
    if (rc < 0) fail("cannot set stream parameters", rc);
    stream->time_base = codec->time_base;
    stream->avg_frame_rate = rate;
    rc = avio_open(&format->pb, temp.c_str(), AVIO_FLAG_WRITE);
    if (rc < 0) fail("cannot open for writing", rc);
    rc = avformat_write_header(format, nullptr);
    if (rc < 0) fail("cannot write the MP4 header", rc);

    sws = sws_getContext(width, height, AV_PIX_FMT_RGB24, width, height, AV_PIX_FMT_YUV420P,
                         SWS_BICUBIC | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
    if (!sws) throw OutputError(file.final_path().string() + ": cannot set up colour conversion");
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
    yuv = av_frame_alloc();
    packet = av_packet_alloc();
    if (!yuv || !packet) throw OutputError(file.final_path().string() + ": out of memory");
    yuv->format = AV_PIX_FMT_YUV420P;
    yuv->width = width;
    yuv->height = height;
    yuv->color_primaries = AVCOL_PRI_BT709;
    yuv->color_trc = AVCOL_TRC_BT709;
    yuv->colorspace = AVCOL_SPC_BT709;
    yuv->color_range = AVCOL_RANGE_MPEG;
    rc = av_frame_get_buffer(yuv, 0);
    if (rc < 0) fail("cannot allocate a frame", rc);
  }

  void drain() {
    for (;;) {
      int rc = avcodec_receive_packet(codec, packet);
      if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return;
      if (rc < 0) fail("encoding failed", rc);
      if (packet->duration == 0) packet->duration = 1;
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      rc = av_interleaved_write_frame(format, packet);
      if (rc < 0) fail("write failed (disk full?)", rc);
    }
  }

  void encode(const cv::Mat& rgb8, double time_s) {
    cv::Mat padded = rgb8;
    if (rgb8.cols != width || rgb8.rows != height)
      cv::copyMakeBorder(rgb8, padded, 0, height - rgb8.rows, 0, width - rgb8.cols, cv::BORDER_REPLICATE);
    int rc = av_frame_make_writable(yuv);
    if (rc < 0) fail("cannot write a frame", rc);
    const uint8_t* src[1] = {padded.ptr<uint8_t>()};
    const int src_stride[1] = {int(padded.step[0])};
    sws_scale(sws, src, src_stride, 0, height, yuv->data, yuv->linesize);
    std::int64_t pts = std::llround(time_s * av_q2d(rate));
    if (pts <= last_pts) pts = last_pts + 1;
    last_pts = pts;
    yuv->pts = pts;
    rc = avcodec_send_frame(codec, yuv);
    if (rc < 0) fail("encoding failed", rc);
    drain();
  }

  void close() {
    if (!format) throw OutputError(file.final_path().string() + ": no frame was written");
    int rc = avcodec_send_frame(codec, nullptr);
    if (rc < 0) fail("encoding failed", rc);
    drain();
    rc = av_write_trailer(format);
    if (rc < 0) fail("cannot finalise the MP4 file", rc);
    rc = avio_closep(&format->pb);
    if (rc < 0) fail("cannot close (disk full?)", rc);
    file.commit();
  }
};

VideoWriter::VideoWriter(const std::string& path, const VideoOptions& options)
    : impl_(std::make_unique<Impl>(path, options)) {
  if (!(options.frames_per_second > 0)) throw UsageError("--fps: frame rate must be positive");
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::write(const DisplayFrame& frame) {
  CV_Assert(frame.code.type() == CV_8UC3);
  if (!impl_->format) impl_->open(frame.code.cols, frame.code.rows);
  impl_->encode(frame.code, frame.time_s);
}

void VideoWriter::finish() { impl_->close(); }

}  // namespace eyestream::io
