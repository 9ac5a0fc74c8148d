// H.264 or HEVC in MP4 or Matroska through the FFmpeg libraries
// (libavformat, libavcodec, libswscale), SDR BT.709 or HDR10.
#pragma once

#include <memory>
#include <string>

#include "io/frame_sink.hpp"

namespace eyestream::io {

struct VideoOptions {
  double frames_per_second = 30.0;
  std::string codec = "auto";     // h264 (libx264), hevc (libx265), auto: h264 at 8 bits, else hevc
  int bit_depth = 8;              // 8, or 10 (hevc)
  bool hdr10 = false;             // 10-bit, PQ, BT.2020, with mastering-display metadata
  bool hlg = false;               // 10-bit, HLG, BT.2020 tags for HLG code the caller prepared
  double hdr10_peak_cd_m2 = 1000; // mastering display peak (and MaxCLL) for HDR10
  int crf = 18;                   // constant rate factor, 0 (lossless) .. 51
  int keyint = 250;               // longest distance between keyframes (1: every frame)
  int b_frames = -1;              // most B-frames in a row; -1: the speed preset's
  int lookahead = -1;             // frames x264's rate control looks ahead (H.264 only); -1: the speed preset's
  std::string preset = "medium";  // encoder speed preset
  int encoder_threads = 2;        // fixed, so output bytes do not depend on --threads
  bool sliced_threads = false;    // H.264: the threads code slices of each frame, not frames (less memory)
  std::string stream_format = "mkv";  // container on standard output (path "-"): mkv or mp4 (fragmented)
};

// Writes display-encoded RGB frames as 4:2:0 video in MP4 or, for a .mkv
// path, Matroska: 8-bit H.264 or HEVC (code CV_8UC3), 10-bit HEVC (code
// CV_16UC3, full 16-bit scale), limited range, tagged BT.709 primaries,
// transfer and matrix; or HDR10 (code CV_16UC3 PQ BT.2020, tagged so, with
// mastering-display and content-light metadata). Odd frame sizes are padded
// by one edge pixel. The path "-" streams to standard output (nothing is
// staged there). Timestamps come from DisplayFrame::time_s at
// 1/frames_per_second resolution. UsageError for a combination the
// encoders cannot make (10-bit H.264).
class VideoWriter : public FrameSink {
 public:
  VideoWriter(const std::string& path, const VideoOptions& options);
  ~VideoWriter() override;
  SinkNeeds needs() const override { return needs_for(options_); }
  // What a writer with these options needs, without opening anything.
  static SinkNeeds needs_for(const VideoOptions& options);
  void write(const DisplayFrame& frame) override;
  void finish() override;

 private:
  struct Impl;
  VideoOptions options_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace eyestream::io
