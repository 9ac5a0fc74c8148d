// H.264 in MP4 through the FFmpeg libraries (libavformat, libavcodec,
// libswscale), tagged BT.709 primaries, transfer and matrix.
#pragma once

#include <memory>
#include <string>

#include "io/frame_sink.hpp"

namespace eyestream::io {

struct VideoOptions {
  double frames_per_second = 30.0;
  int crf = 18;                   // x264 constant rate factor, 0 (lossless) .. 51
  std::string preset = "medium";  // x264 speed preset
  int encoder_threads = 2;        // fixed, so output bytes do not depend on --threads
};

// Writes 8-bit display-encoded RGB frames as yuv420p H.264 (libx264), limited
// range, BT.709 matrix. Odd frame sizes are padded by one edge pixel (4:2:0
// needs even sizes). Timestamps come from DisplayFrame::time_s at
// 1/frames_per_second resolution.
class VideoWriter : public FrameSink {
 public:
  VideoWriter(const std::string& path, const VideoOptions& options);
  ~VideoWriter() override;
  SinkNeeds needs() const override { return SinkNeeds::kCode8; }
  void write(const DisplayFrame& frame) override;
  void finish() override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace eyestream::io
