#include "io/sink_factory.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "io/error.hpp"
#include "io/exr_file.hpp"
#include "io/frame_sequence.hpp"
#include "io/image_sequence_sink.hpp"

namespace eyestream::io {

namespace {

std::string output_kind(const std::string& path) {
  if (path == "-") return ".stream";
  const std::string ext = lower_extension(path);
  if (ext != ".mp4" && ext != ".mkv" && ext != ".png" && ext != ".exr")
    throw UsageError("-o " + path + ": unknown output kind (use .mp4, .mkv, .png or .exr)");
  return ext;
}

}  // namespace

std::unique_ptr<FrameSink> make_sink(const std::string& path, const SinkOptions& options) {
  const std::string ext = output_kind(path);
  if (ext == ".mp4" || ext == ".mkv" || ext == ".stream") return std::make_unique<VideoWriter>(path, options.video);
  if (ext == ".png")
    return std::make_unique<ImageSequenceSink>(path, options.png_bits == 16 ? ImageFormat::kPng16 : ImageFormat::kPng8,
                                               0, 0.0, options.png_gamma);
  return std::make_unique<ImageSequenceSink>(path, ImageFormat::kExr, 0, options.video.frames_per_second, 1.0 / 2.2,
                                             exr_compression_named(options.exr_compression));
}

SinkNeeds sink_needs(const std::string& path, const SinkOptions& options) {
  const std::string ext = output_kind(path);
  if (ext == ".exr") return SinkNeeds::kLinear;
  if (ext == ".mp4" || ext == ".mkv" || ext == ".stream") return VideoWriter::needs_for(options.video);
  return ext == ".png" && options.png_bits == 16 ? SinkNeeds::kCode16 : SinkNeeds::kCode8;
}

}  // namespace eyestream::io
