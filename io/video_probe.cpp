#include "io/video_probe.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
}

#include "io/error.hpp"

namespace eyestream::io {

namespace {
std::string or_unknown(const char* s) { return s ? s : "unknown"; }
}  // namespace

VideoProbe probe_video(const std::string& path) {
  AVFormatContext* fmt = nullptr;
  if (avformat_open_input(&fmt, path.c_str(), nullptr, nullptr) < 0) throw InputError(path + ": cannot open video");
  struct Closer {
    AVFormatContext** f;
    ~Closer() { avformat_close_input(f); }
  } closer{&fmt};
  if (avformat_find_stream_info(fmt, nullptr) < 0) throw InputError(path + ": cannot read stream information");
  int index = av_find_best_stream(fmt, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (index < 0) throw InputError(path + ": no video stream");
  const AVCodecParameters* par = fmt->streams[index]->codecpar;
  VideoProbe p;
  p.codec = avcodec_get_name(par->codec_id);
  p.pixel_format = or_unknown(av_get_pix_fmt_name(AVPixelFormat(par->format)));
  p.color_primaries = or_unknown(av_color_primaries_name(par->color_primaries));
  p.color_transfer = or_unknown(av_color_transfer_name(par->color_trc));
  p.color_space = or_unknown(av_color_space_name(par->color_space));
  p.width = par->width;
  p.height = par->height;
  p.duration_s = fmt->duration > 0 ? double(fmt->duration) / AV_TIME_BASE : 0.0;
  p.frames_per_second = av_q2d(fmt->streams[index]->avg_frame_rate);
  AVPacket* pkt = av_packet_alloc();
  while (av_read_frame(fmt, pkt) >= 0) {
    if (pkt->stream_index == index) ++p.frame_count;
    av_packet_unref(pkt);
  }
  av_packet_free(&pkt);
  return p;
}

}  // namespace eyestream::io
