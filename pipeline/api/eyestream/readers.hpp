// eyestream's readers as a library: the frames and gaze logs `eyestream
// run` reads, read the same way (the same option names), one frame at a
// time, for a program that feeds an eyestream::Eye itself.
//
//   eyestream::FrameReader frames("drive/frames/%05d.exr");
//   std::vector<eyestream::Gaze> gaze = eyestream::read_gaze("drive/gaze.csv", frames.width(), frames.height(),
//                                                           frames.fps());
//   for (eyestream::InputFrame f; frames.next(f);) ...
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "eyestream/eye.hpp"

namespace eyestream {

struct InputFrame {
  cv::Mat rgb_cd_m2;        // linear Rec.709 RGB in cd/m^2, CV_32FC3
  double time_s = 0.0;      // from the first frame
  std::int64_t index = 0;   // the frame's position in the input
};

class FrameReader {
 public:
  // `path` as `eyestream run -i` takes it: an EXR sequence (printf pattern,
  // folder or file), an HDR video, .hdr/.pfm/.tif stills, or "-" (raw
  // float RGB on standard input with "size"). `settings` as for Eye: the
  // input options ("fps", "scale", "layer", "video-transfer", "video-peak",
  // "size", "skip-missing", ...). Error (exit code 3) when it cannot be read.
  explicit FrameReader(const std::string& path, const std::map<std::string, std::string>& settings = {});
  ~FrameReader();
  FrameReader(FrameReader&&) noexcept;
  FrameReader& operator=(FrameReader&&) noexcept;

  int width() const;
  int height() const;
  double fps() const;                 // the input's nominal rate
  std::int64_t frame_count() const;   // -1 when unknown (streams)
  std::string description() const;   // e.g. "EXR sequence, 180 frames, half"

  // The next frame into `frame`; false at the end. Error naming the file
  // and frame when one cannot be read.
  bool next(InputFrame& frame);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A gaze log or eye-tracker export (native CSV, Pupil Core, Neon, Tobii,
// EyeLink) as `eyestream run -g` reads it, for a width x height stream at
// fps frames/s: times from the first frame, frame pixels. `settings` as for
// Eye: the gaze options ("gaze-format", "gaze-units", "gaze-sync",
// "gaze-recording", "gaze-pupil-scale", ...).
std::vector<Gaze> read_gaze(const std::string& path, int width, int height, double fps,
                            const std::map<std::string, std::string>& settings = {});

}  // namespace eyestream
