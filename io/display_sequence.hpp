// Display-referred frames for comparison (`eyestream compare`): a PNG or
// EXR sequence (printf pattern, folder or single file) or a video file.
#pragma once

#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/frame_sequence.hpp"
#include "io/video_reader.hpp"

namespace eyestream::io {

struct DisplayImage {
  cv::Mat rgb;  // CV_32FC3, R, G, B
  std::string name;  // file, or file and frame number, for messages
  std::int64_t number = 0;  // the frame's number: in the file pattern, or the video's frame index
};

class DisplaySequence {
 public:
  // A path ending in .png/.exr/.tif/.tiff (or a folder of them) is an
  // image sequence; anything else is opened as a video. InputError naming
  // the path when it cannot be read.
  explicit DisplaySequence(const std::string& path);
  // PNG, TIFF and video frames hold display code values (0..1, decoded to
  // light with gamma 2.2, eyestream's own encoding inverted); EXR frames
  // hold display-linear values.
  bool linear() const { return linear_; }
  // Frames when known in advance; -1 for a video whose container does not say.
  std::int64_t frame_count() const;
  std::optional<DisplayImage> next();

 private:
  std::string path_;
  std::vector<SequenceEntry> files_;
  std::unique_ptr<VideoReader> video_;
  size_t position_ = 0;
  bool linear_ = false;
};

}  // namespace eyestream::io
