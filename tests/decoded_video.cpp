#include "tests/decoded_video.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

namespace eyestream::test {

int for_each_decoded_frame(const std::string& path, const std::function<bool(const AVFrame&)>& take) {
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
  int given = 0;
  bool more = true;
  const auto drain = [&] {
    while (more && avcodec_receive_frame(c, frame) >= 0) {
      ++given;
      more = take(*frame);
    }
  };
  while (more && av_read_frame(in, packet) >= 0) {
    if (packet->stream_index == s) avcodec_send_packet(c, packet);
    av_packet_unref(packet);
    drain();
  }
  if (more) {
    avcodec_send_packet(c, nullptr);
    drain();
  }
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&c);
  avformat_close_input(&in);
  return given;
}

}  // namespace eyestream::test
