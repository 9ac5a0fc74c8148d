#include "io/video_concat.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/mastering_display_metadata.h>
}

#include <algorithm>
#include <cstring>
#include <memory>

#include "io/av_error.hpp"
#include "io/error.hpp"
#include "io/staged_file.hpp"

namespace eyestream::io {

namespace {

struct InputFile {
  AVFormatContext* format = nullptr;
  int stream = -1;
  ~InputFile() { avformat_close_input(&format); }
};

std::unique_ptr<InputFile> open_input(const std::string& path) {
  auto in = std::make_unique<InputFile>();
  if (avformat_open_input(&in->format, path.c_str(), nullptr, nullptr) < 0) throw InputError(path + ": cannot open");
  if (avformat_find_stream_info(in->format, nullptr) < 0) throw InputError(path + ": cannot read its streams");
  in->stream = av_find_best_stream(in->format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (in->stream < 0) throw InputError(path + ": no video stream");
  return in;
}

// The HDR metadata the joined video carries: the first chunk's mastering
// display, and a content light level that is the largest of the chunks'
// (MaxCLL is a maximum over frames, MaxFALL a maximum of frame means), or
// none when a chunk has none.
struct LightMetadata {
  std::vector<uint8_t> mastering;
  bool has_level = true;
  AVContentLightMetadata level{};
};

LightMetadata light_metadata(const std::vector<std::string>& inputs) {
  LightMetadata m;
  for (size_t k = 0; k < inputs.size(); ++k) {
    std::unique_ptr<InputFile> in = open_input(inputs[k]);
    const AVStream* src = in->format->streams[in->stream];
    size_t size = 0;
    const uint8_t* d = av_stream_get_side_data(src, AV_PKT_DATA_MASTERING_DISPLAY_METADATA, &size);
    if (k == 0 && d) m.mastering.assign(d, d + size);
    d = av_stream_get_side_data(src, AV_PKT_DATA_CONTENT_LIGHT_LEVEL, &size);
    if (!d || size < sizeof(AVContentLightMetadata)) {
      m.has_level = false;
      continue;
    }
    const auto* l = reinterpret_cast<const AVContentLightMetadata*>(d);
    if (l->MaxCLL == 0 && l->MaxFALL == 0) m.has_level = false;  // 0: unknown
    m.level.MaxCLL = std::max(m.level.MaxCLL, l->MaxCLL);
    m.level.MaxFALL = std::max(m.level.MaxFALL, l->MaxFALL);
  }
  return m;
}

struct PacketFree {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
using Packet = std::unique_ptr<AVPacket, PacketFree>;

// A chunk's video packets in decode order, timed in `time_base` (held in
// memory: a chunk's compressed frames). Matroska stores presentation times
// only, so its demuxer leaves most decode times unset; they are made again
// here as a muxer needs them: the presentation times in order, moved back
// by `delay` (the codec's reordering depth in frames), or more if this
// chunk reorders deeper, so each packet is decoded no later than it is
// shown and, with one delay for every chunk, the times rise across chunks.
std::vector<Packet> chunk_packets(InputFile& in, const std::string& path, AVRational time_base,
                                  std::int64_t delay) {
  std::vector<Packet> packets;
  const AVRational src = in.format->streams[in.stream]->time_base;
  bool missing = false;
  for (;;) {
    Packet p(av_packet_alloc());
    if (!p) throw InputError(path + ": out of memory");
    const int rc = av_read_frame(in.format, p.get());
    if (rc == AVERROR_EOF) break;
    if (rc < 0) throw InputError(path + ": cannot read its packets");
    if (p->stream_index != in.stream) continue;
    av_packet_rescale_ts(p.get(), src, time_base);
    missing = missing || p->dts == AV_NOPTS_VALUE;
    packets.push_back(std::move(p));
  }
  if (!missing) return packets;
  std::vector<std::int64_t> shown;
  for (const Packet& p : packets) {
    if (p->pts == AV_NOPTS_VALUE) throw InputError(path + ": packets without times; cannot join it");
    shown.push_back(p->pts);
  }
  std::sort(shown.begin(), shown.end());
  for (size_t i = 0; i < packets.size(); ++i) delay = std::max(delay, shown[i] - packets[i]->pts);
  for (size_t i = 0; i < packets.size(); ++i) packets[i]->dts = shown[i] - delay;
  return packets;
}

// The earliest presentation time of a chunk's packets.
std::int64_t chunk_start(const std::vector<Packet>& packets) {
  std::int64_t start = AV_NOPTS_VALUE;
  for (const Packet& p : packets)
    if (p->pts != AV_NOPTS_VALUE && (start == AV_NOPTS_VALUE || p->pts < start)) start = p->pts;
  return start;
}

void add_side_data(AVStream* stream, AVPacketSideDataType type, const void* data, size_t size) {
  uint8_t* copy = static_cast<uint8_t*>(av_malloc(size));
  if (!copy) return;
  std::memcpy(copy, data, size);
  if (av_stream_add_side_data(stream, type, copy, size) < 0) av_free(copy);
}

}  // namespace

void concat_videos(const std::vector<std::string>& inputs, const std::string& output) {
  if (inputs.empty()) throw UsageError("concat: no input");
  for (const std::string& path : inputs) protect_input(path);
  StagedFile file(output);
  const std::string ext = file.final_path().extension().string();
  const bool mkv = ext == ".mkv";
  const LightMetadata light = light_metadata(inputs);
  AVFormatContext* out = nullptr;
  if (avformat_alloc_output_context2(&out, nullptr, mkv ? "matroska" : "mp4",
                                     file.temp_path().c_str()) < 0)
    throw OutputError(output + ": cannot set up the container");
  struct Closer {
    AVFormatContext* f;
    ~Closer() {
      if (f && f->pb) avio_closep(&f->pb);
      avformat_free_context(f);
    }
  } closer{out};
  out->flags |= AVFMT_FLAG_BITEXACT;
  AVStream* stream = avformat_new_stream(out, nullptr);
  std::int64_t last_dts = AV_NOPTS_VALUE, last_end = AV_NOPTS_VALUE;
  const AVCodecParameters* first = nullptr;
  std::unique_ptr<InputFile> first_input;
  for (size_t k = 0; k < inputs.size(); ++k) {
    std::unique_ptr<InputFile> in = open_input(inputs[k]);
    const AVStream* src = in->format->streams[in->stream];
    if (!first) {
      if (avcodec_parameters_copy(stream->codecpar, src->codecpar) < 0) throw OutputError(output + ": out of memory");
      // HEVC in MP4 as 'hvc1', as `run` writes it (Apple's players refuse 'hev1').
      stream->codecpar->codec_tag =
          !mkv && src->codecpar->codec_id == AV_CODEC_ID_HEVC ? MKTAG('h', 'v', 'c', '1') : 0;
      stream->time_base = src->time_base;
      stream->avg_frame_rate = src->avg_frame_rate;
      if (!light.mastering.empty())
        add_side_data(stream, AV_PKT_DATA_MASTERING_DISPLAY_METADATA, light.mastering.data(), light.mastering.size());
      if (light.has_level)
        add_side_data(stream, AV_PKT_DATA_CONTENT_LIGHT_LEVEL, &light.level, sizeof(light.level));
      if (avio_open(&out->pb, file.temp_path().c_str(), AVIO_FLAG_WRITE) < 0)
        throw OutputError(output + ": cannot open for writing");
      AVDictionary* muxer = nullptr;
      if (!mkv) av_dict_set(&muxer, "movflags", "faststart", 0);  // the index first, as `run` writes it
      const int rc = avformat_write_header(out, &muxer);
      av_dict_free(&muxer);
      if (rc < 0) throw OutputError(output + ": cannot write the header");
      first = src->codecpar;
    } else if (src->codecpar->codec_id != first->codec_id || src->codecpar->width != first->width ||
               src->codecpar->height != first->height) {
      throw InputError(inputs[k] + ": another codec or frame size than " + inputs[0]);
    } else if (src->codecpar->format != first->format || src->codecpar->color_trc != first->color_trc ||
               src->codecpar->color_primaries != first->color_primaries ||
               src->codecpar->color_space != first->color_space ||
               src->codecpar->color_range != first->color_range) {
      throw InputError(inputs[k] + ": another pixel format or colour (transfer, primaries, matrix, range) than " +
                       inputs[0] + ": the chunks were made with other settings");
    } else if (src->codecpar->profile != first->profile || src->codecpar->extradata_size != first->extradata_size ||
               (first->extradata_size > 0 &&
                std::memcmp(src->codecpar->extradata, first->extradata, size_t(first->extradata_size)) != 0)) {
      // The joined file keeps the first chunk's codec headers: another
      // encoder setting (--quality, --crf) would decode as corrupt video.
      throw InputError(inputs[k] + ": encoded with other settings than " + inputs[0] +
                       " (its codec headers differ): make every chunk with the same options");
    }
    // One frame in the output's time base, and the codec's reordering depth.
    const std::int64_t frame =
        std::max<std::int64_t>(1, av_rescale_q(1, av_inv_q(src->avg_frame_rate.num > 0 ? src->avg_frame_rate
                                                                                      : src->r_frame_rate),
                                               stream->time_base));
    const std::vector<Packet> chunk =
        chunk_packets(*in, inputs[k], stream->time_base, std::int64_t(first->video_delay) * frame);
    if (chunk.empty()) throw InputError(inputs[k] + ": holds no frames");
    // A chunk that starts more than a frame and a half after the previous
    // one ended leaves a hole: a chunk is missing (a failed task).
    const std::int64_t first_pts = chunk_start(chunk);
    if (last_end != AV_NOPTS_VALUE && first_pts != AV_NOPTS_VALUE && first_pts - last_end > frame * 3 / 2)
      throw InputError(inputs[k] + ": starts " +
                       std::to_string(double(first_pts - last_end) * av_q2d(stream->time_base)) +
                       " s after the previous chunk ends: is a chunk missing between them?");
    for (const Packet& p : chunk) {
      if (last_dts != AV_NOPTS_VALUE && p->dts != AV_NOPTS_VALUE && p->dts <= last_dts)
        throw InputError(inputs[k] + ": its frames overlap the previous chunk's (are the chunks in order?)");
      if (p->dts != AV_NOPTS_VALUE) last_dts = p->dts;
      if (p->pts != AV_NOPTS_VALUE)
        last_end = std::max(last_end, p->pts + (p->duration > 0 ? p->duration : frame));
      p->stream_index = stream->index;
      p->pos = -1;
      const int rc = av_interleaved_write_frame(out, p.get());
      if (rc < 0) throw OutputError(output + ": cannot write " + inputs[k] + "'s packets: " + av_error_text(rc));
    }
    if (k == 0) first_input = std::move(in);  // keeps `first` valid
  }
  if (av_write_trailer(out) < 0) throw OutputError(output + ": cannot finalise");
  if (avio_closep(&out->pb) < 0) throw OutputError(output + ": cannot close (disk full?)");
  file.commit();
}

}  // namespace eyestream::io
