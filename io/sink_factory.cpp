#include "io/sink_factory.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "io/error.hpp"
#include "io/image_sequence_sink.hpp"

namespace eyestream::io {

std::unique_ptr<FrameSink> make_sink(const std::string& path, const SinkOptions& options) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".mp4") return std::make_unique<VideoWriter>(path, options.video);
  if (ext == ".png")
    return std::make_unique<ImageSequenceSink>(path, options.png_bits == 16 ? ImageFormat::kPng16 : ImageFormat::kPng8);
  if (ext == ".exr") return std::make_unique<ImageSequenceSink>(path, ImageFormat::kExr);
  throw UsageError("-o " + path + ": unknown output kind (use .mp4, .png or .exr)");
}

}  // namespace eyestream::io
