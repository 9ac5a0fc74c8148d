#include "io/raw_stream_source.hpp"

#include <cstdio>

#include "io/error.hpp"

namespace eyestream::io {

void parse_frame_size(const std::string& text, int& width, int& height) {
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 || (x != 'x' && x != 'X') ||
      width < 1 || height < 1)
    throw UsageError("--size '" + text + "': expected WIDTHxHEIGHT, e.g. 1920x1080");
  if (width > 65536 || height > 65536)
    throw UsageError("--size '" + text + "': at most 65536 pixels a side");
}

RawStreamSource::RawStreamSource(std::FILE* stream, std::string name, const RawStreamOptions& o)
    : stream_(stream), name_(std::move(name)), options_(o) {
  if (o.width < 1 || o.height < 1) throw UsageError("-i -: raw frames on standard input need --size WxH");
  if (!(o.frames_per_second > 0)) throw UsageError("--fps: frame rate must be positive");
  info_.width = o.width;
  info_.height = o.height;
  info_.frames_per_second = o.frames_per_second;
  info_.frame_count = -1;
  info_.description = "raw float RGB frames on " + name_;
}

std::optional<SceneFrame> RawStreamSource::next() {
  cv::Mat rgb(options_.height, options_.width, CV_32FC3);
  const size_t want = rgb.total() * rgb.elemSize();
  const size_t got = std::fread(rgb.data, 1, want, stream_);
  if (got == 0 && std::feof(stream_)) return std::nullopt;
  if (got != want) {
    const std::string message = name_ + ": frame " + std::to_string(index_) + " is truncated (" +
                                std::to_string(got) + " of " + std::to_string(want) + " bytes)";
    if (!options_.stop_on_truncated) throw InputError(message);
    std::fprintf(stderr, "eyestream: warning: %s; stopping after %lld frames (--on-bad-video stop)\n",
                 message.c_str(), (long long)index_);
    return std::nullopt;
  }
  if (options_.scale != 1.0) rgb *= options_.scale;
  SceneFrame f;
  f.rgb = rgb;
  f.index = index_;
  f.time_s = double(index_) / options_.frames_per_second;
  f.source = name_;
  ++index_;
  return f;
}

}  // namespace eyestream::io
