// Chooses the output kind from the output path's extension.
#pragma once

#include <memory>
#include <string>

#include "io/frame_sink.hpp"
#include "io/video_writer.hpp"

namespace eyestream::io {

struct SinkOptions {
  VideoOptions video;
  int png_bits = 8;  // 8 or 16
  double png_gamma = 1.0 / 2.2;  // the display encoding's power, for PNG's gAMA
  std::string exr_compression = "zip";  // io::exr_compression_named's names
};

// .mp4/.mkv -> video; "-" -> video on standard output (--format); .png ->
// PNG sequence; .exr -> EXR sequence. Any other
// extension is a UsageError naming the path.
std::unique_ptr<FrameSink> make_sink(const std::string& path, const SinkOptions& options);

// What the sink make_sink would return needs, without creating anything.
SinkNeeds sink_needs(const std::string& path, const SinkOptions& options);

}  // namespace eyestream::io
