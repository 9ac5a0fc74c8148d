// The frame currencies that cross module boundaries.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

namespace eyestream::io {

// A decoded scene-referred frame: linear Rec.709 RGB in cd/m^2 (CV_32FC3,
// channel order R, G, B). Values may be negative (out of gamut), zero, or
// non-finite if the file holds them; consumers decide the policy.
struct SceneFrame {
  cv::Mat rgb;
  double time_s = 0.0;     // presentation time from the first frame
  std::int64_t index = 0;  // position in the stream, 0-based
  std::string source;      // file name (or stream name) for messages
  // Pixels with a NaN or infinite channel, when the source counted them
  // (-1: not counted).
  std::int64_t nonfinite = -1;
};

// A display-referred frame ready for writing. `linear` is display-linear
// relative RGB (CV_32FC3, 1 = display peak, before encoding and dithering);
// `code` holds the encoded, dithered values (CV_8UC3 or CV_16UC3, R, G, B)
// when the sink asked for them.
struct DisplayFrame {
  cv::Mat linear;
  cv::Mat code;
  double time_s = 0.0;
  std::int64_t index = 0;
};

}  // namespace eyestream::io
