// The interface every output implements (video file, PNG or EXR sequence).
#pragma once

#include "io/frame.hpp"

namespace eyestream::io {

// What a sink needs of each DisplayFrame.
enum class SinkNeeds {
  kLinear,  // DisplayFrame::linear (float, before encoding and dithering)
  kCode8,   // DisplayFrame::code, CV_8UC3
  kCode16,  // DisplayFrame::code, CV_16UC3
  kPq16,    // DisplayFrame::code, CV_16UC3: PQ-encoded BT.2020 (HDR10)
};

// A sink writes frames under temporary names; finish() finalises them and
// moves them into place. A sink destroyed without finish() removes what it
// wrote: no partial output is left behind. Errors are OutputError naming the
// file.
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual SinkNeeds needs() const = 0;
  virtual void write(const DisplayFrame& frame) = 0;
  virtual void finish() = 0;
  // Moves the frames written so far into place (checkpoints: they must
  // survive a crash). False when the output cannot do that (a video).
  virtual bool commit_so_far() { return false; }
};

}  // namespace eyestream::io
