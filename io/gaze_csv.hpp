// The native gaze-log format: CSV with header `t,x,y` and an optional
// `event` column (empty, fixation, saccade, blink, lost).
#pragma once

#include <string>
#include <vector>

#include "io/gaze_sample.hpp"

namespace eyestream::io {

enum class GazeUnits { kPixels, kNormalised };

// Parses a native gaze log (read files with io::read_gaze). Positions in
// kNormalised units (0..1 of the frame) are scaled by frame_width x
// frame_height. Blink and lost samples may leave x and y empty. Times must
// be finite and strictly increasing. Any malformed line is an InputError
// naming the file (`name`) and line number.
std::vector<GazeSample> parse_gaze_csv(const std::string& text, const std::string& name, GazeUnits units,
                                       int frame_width, int frame_height);

// Writes samples in the native format (pixels), atomically.
void write_gaze_csv(const std::string& path, const std::vector<GazeSample>& samples);

}  // namespace eyestream::io
