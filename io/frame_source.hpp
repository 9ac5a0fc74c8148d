// The interface every frame input implements (EXR sequences now; video
// files, stills and standard input beside it).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "io/frame.hpp"

namespace eyestream::io {

struct SourceInfo {
  int width = 0, height = 0;
  double frames_per_second = 0.0;  // nominal rate; frame times may vary
  std::int64_t frame_count = -1;   // -1 when unknown (streams)
  std::string description;         // e.g. "EXR sequence, 180 frames, half"
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  virtual const SourceInfo& info() const = 0;
  // The next frame in presentation order, or nothing at the end. Throws
  // InputError naming the file and frame on a bad frame.
  virtual std::optional<SceneFrame> next() = 0;
  // Whether the source knows its frames' times without decoding them (file
  // sequences: from the file numbers). Then time_of(index) is the time of
  // the frame next() numbers `index`, or nothing if there is no such
  // frame; it reads only what the constructor set, so it may be called
  // while another thread is in next().
  virtual bool knows_times() const { return false; }
  virtual std::optional<double> time_of(std::int64_t /*index*/) const { return std::nullopt; }
};

}  // namespace eyestream::io
