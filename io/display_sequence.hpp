// Display-referred frames for comparison (`eyestream compare`): a PNG or
// EXR sequence (printf pattern, folder or single file) or a video file
// (SDR, or PQ/HLG decoded to light).
#pragma once

#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/frame_sequence.hpp"
#include "io/video_reader.hpp"
#include "io/video_source.hpp"

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
  // `layer`: the layer of layered EXRs (as run's --layer; "" the beauty pass).
  explicit DisplaySequence(const std::string& path, const std::string& layer = "");
  // PNG, TIFF and SDR video frames hold display code values (0..1, decoded
  // to light with gamma 2.2, eyestream's own encoding inverted); EXR frames
  // hold display-linear values. A video tagged PQ or HLG is decoded to
  // light by its tags (the transfer, HLG's OOTF at a 1000 cd/m^2 nominal
  // peak, BT.2020 primaries to Rec.709) and given relative to the BT.2408
  // reference white, 203 cd/m^2.
  enum class Kind { kCode, kLinear, kHdrLight };
  Kind kind() const { return kind_; }
  bool linear() const { return kind_ != Kind::kCode; }
  static constexpr double kHdrReferenceWhite = 203.0;  // cd/m^2, ITU-R BT.2408
  const char* kind_name() const;  // for messages
  // Frames when known in advance; -1 for a video whose container does not say.
  std::int64_t frame_count() const;
  std::optional<DisplayImage> next();

 private:
  std::string path_, layer_;
  std::vector<SequenceEntry> files_;
  std::unique_ptr<VideoReader> video_;
  std::unique_ptr<VideoSource> hdr_;  // a PQ or HLG video, decoded to light
  size_t position_ = 0;
  Kind kind_ = Kind::kCode;
};

}  // namespace eyestream::io
