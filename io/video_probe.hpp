// What a video file holds, read back through libavformat: used by tests and
// by tools that check an encoded output.
#pragma once

#include <cstdint>
#include <string>

namespace eyestream::io {

struct VideoProbe {
  std::string codec;            // e.g. "h264"
  std::string pixel_format;     // e.g. "yuv420p"
  std::string color_primaries;  // e.g. "bt709"
  std::string color_transfer;
  std::string color_space;
  int width = 0, height = 0;
  std::int64_t frame_count = 0;  // packets of the video stream, counted
  double duration_s = 0.0;       // container duration
  double frames_per_second = 0.0;
};

// Probes the first video stream of `path`; InputError if unreadable.
VideoProbe probe_video(const std::string& path);

}  // namespace eyestream::io
