// The gaze tests' import options: a 1000x500 input frame.
#pragma once

#include "io/gaze_import.hpp"

namespace eyestream::test {

inline io::GazeImportOptions frame_1000x500() {
  io::GazeImportOptions o;
  o.frame_width = 1000;
  o.frame_height = 500;
  return o;
}

}  // namespace eyestream::test
