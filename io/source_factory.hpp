// Chooses the frame input from the input path: EXR sequences (pattern,
// folder or .exr file) or a video file.
#pragma once

#include <memory>
#include <string>

#include "io/exr_sequence_source.hpp"
#include "io/frame_source.hpp"
#include "io/video_source.hpp"

namespace eyestream::io {

struct SourceOptions {
  ExrSequenceOptions exr;
  VideoSourceOptions video;
  std::string raw_size;  // WxH of raw frames on standard input
};

// "-" is raw float frames on standard input (raw_stream_source.hpp);
// .hdr or .pfm stills (a file, pattern or folder of them) are read by
// OpenCV; a printf pattern, a folder or a .exr file is an EXR sequence;
// any other file is opened as a video. InputError naming the input
// otherwise.
std::unique_ptr<FrameSource> open_source(const std::string& input, const SourceOptions& options);

}  // namespace eyestream::io
