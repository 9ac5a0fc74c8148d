#include "io/source_factory.hpp"

#include <algorithm>
#include <filesystem>

#include "io/error.hpp"
#include "io/float_image_source.hpp"
#include "io/frame_sequence.hpp"
#include "io/raw_stream_source.hpp"

namespace eyestream::io {

std::unique_ptr<FrameSource> open_source(const std::string& input, const SourceOptions& o) {
  if (input == "-") {
    RawStreamOptions raw;
    if (o.raw_size.empty()) throw UsageError("-i -: raw frames on standard input need --size WxH");
    if (!o.exr.layer.empty()) throw UsageError("--layer " + o.exr.layer + ": raw frames on standard input have no layers");
    parse_frame_size(o.raw_size, raw.width, raw.height);
    if (std::int64_t(raw.width) * raw.height > o.exr.max_pixels)
      throw UsageError("--size " + o.raw_size + " exceeds the limit of " + std::to_string(o.exr.max_pixels) +
                       " pixels (--max-pixels)");
    raw.frames_per_second = o.exr.frames_per_second.value_or(o.exr.default_frames_per_second);
    raw.scale = o.exr.scale.value_or(1.0);
    raw.stop_on_truncated = o.video.on_bad_video == "stop";
    return std::make_unique<RawStreamSource>(stdin, "standard input", raw);
  }
  if (!o.raw_size.empty())  // the size of files and videos is their own
    throw UsageError("--size " + o.raw_size + ": only raw frames on standard input (-i -) need it; " + input +
                     " gives its own");
  if (is_float_image_input(input)) {
    if (!o.exr.layer.empty())
      throw UsageError("--layer " + o.exr.layer + ": " + input + " holds stills, which have no layers");
    return std::make_unique<FloatImageSource>(input, o.exr);
  }
  if (is_printf_pattern(input) || lower_extension(input) == ".exr" || std::filesystem::is_directory(input) ||
      !std::filesystem::exists(input))
    return std::make_unique<ExrSequenceSource>(input, o.exr);
  if (!o.exr.layer.empty())  // layers are EXR's
    throw UsageError("--layer " + o.exr.layer + ": " + input + " is a video, which has no layers");
  VideoSourceOptions video = o.video;
  video.max_pixels = o.exr.max_pixels;
  return std::make_unique<VideoSource>(input, video);
}

}  // namespace eyestream::io
