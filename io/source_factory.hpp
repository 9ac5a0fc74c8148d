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
};

// A printf pattern, a folder or a .exr file is an EXR sequence; any other
// file is opened as a video. InputError naming the input otherwise.
std::unique_ptr<FrameSource> open_source(const std::string& input, const SourceOptions& options);

}  // namespace eyestream::io
