// Decodes the frames of a video file (anything libavformat opens) to
// floating-point RGB code values, with the stream's colour tags, for the
// HDR video input and `eyestream compare`.
#pragma once

#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

namespace eyestream::io {

struct VideoColour {
  std::string transfer;   // libavutil names: "smpte2084" (PQ), "arib-std-b67" (HLG), "bt709", "unknown", ...
  std::string primaries;  // "bt2020", "bt709", "unknown", ...
  std::string matrix;     // "bt2020nc", "bt709", ...
  bool full_range = false;
  int bit_depth = 8;
};

struct VideoFrame {
  cv::Mat rgb;  // CV_32FC3, R, G, B: non-linear code values, 0..1 (full range)
  double time_s = 0.0;  // presentation time from the first frame
  std::int64_t index = 0;
};

class VideoReader {
 public:
  // InputError naming the file when it cannot be opened or has no video.
  explicit VideoReader(const std::string& path);
  ~VideoReader();
  VideoReader(const VideoReader&) = delete;
  VideoReader& operator=(const VideoReader&) = delete;

  int width() const;
  int height() const;
  double frames_per_second() const;   // the stream's average rate (0 when unknown)
  std::int64_t frame_count() const;   // from the container; -1 when it does not say
  double duration_s() const;          // the container's duration; -1 when it does not say
  const VideoColour& colour() const;
  const std::string& path() const;

  // The next frame in presentation order, or nothing at the end. A packet
  // that does not decode is an InputError naming the file and frame.
  std::optional<VideoFrame> next();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace eyestream::io
