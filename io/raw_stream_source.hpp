// Raw float RGB frames on a stream (`-i -`): a simulator pipes each frame
// as it renders it.
#pragma once

#include <cstdio>
#include <string>

#include "io/frame_source.hpp"

namespace eyestream::io {

struct RawStreamOptions {
  int width = 0, height = 0;      // --size WxH (required)
  double frames_per_second = 30;  // --fps
  double scale = 1.0;             // cd/m^2 per unit (--scale)
  bool stop_on_truncated = false; // --on-bad-video stop: a stream ending inside a frame ends before it
};

// Each frame is width * height * 3 native-endian 32-bit floats, R, G, B
// interleaved, rows top to bottom, linear Rec.709 (cd/m^2 after scale).
// Frame k's time is k / fps. A stream ending inside a frame is an
// InputError naming the frame and the bytes it got.
class RawStreamSource : public FrameSource {
 public:
  RawStreamSource(std::FILE* stream, std::string name, const RawStreamOptions& options);
  const SourceInfo& info() const override { return info_; }
  std::optional<SceneFrame> next() override;

 private:
  std::FILE* stream_;
  std::string name_;
  RawStreamOptions options_;
  SourceInfo info_;
  std::int64_t index_ = 0;
};

// Parses "WxH" (--size); UsageError otherwise.
void parse_frame_size(const std::string& text, int& width, int& height);

}  // namespace eyestream::io
