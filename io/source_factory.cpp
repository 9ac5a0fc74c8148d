#include "io/source_factory.hpp"

#include <algorithm>
#include <filesystem>

#include "io/frame_sequence.hpp"

namespace eyestream::io {

std::unique_ptr<FrameSource> open_source(const std::string& input, const SourceOptions& o) {
  std::string ext = std::filesystem::path(input).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (is_printf_pattern(input) || ext == ".exr" || std::filesystem::is_directory(input) ||
      !std::filesystem::exists(input))
    return std::make_unique<ExrSequenceSource>(input, o.exr);
  VideoSourceOptions video = o.video;
  video.max_pixels = o.exr.max_pixels;
  return std::make_unique<VideoSource>(input, video);
}

}  // namespace eyestream::io
