// Display encoding: gamma, clipping and temporally dithered quantisation
// (Jacobs et al. 2015 sec. 2.4 and App. A).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

namespace eyestream::retina {

struct EncodingParams {
  double gamma = 0.455;  // display value J^gamma (Jacobs et al. 2015 App. A)
  bool dither = true;    // temporal dithering before quantisation
  std::uint64_t seed = 0;
};

// Encodes display-linear J (CV_32FC3) to `code` with `bits` = 8 or 16:
// v = clamp(J, 0, 1)^gamma * (2^bits - 1), rounded up with probability equal
// to its fractional part (per channel, pixel and frame, from a hash of
// (seed, frame_index, x, y, channel)), else rounded to nearest. Non-finite J
// encodes as 0. Threads over rows; bytes do not depend on the thread count.
void encode_display(const cv::Mat& linear, int bits, std::int64_t frame_index, const EncodingParams& p, cv::Mat& code);

// Row y of that encoding, bit for bit: `cols` pixels of display-linear J
// (3 floats each) into `code_row` (3 uint8 or uint16 each, by `bits`).
// For a pass that makes J row by row and encodes each while it is in the
// cache. Thread-safe; allocates nothing once p.gamma's power table exists
// (the first use of a gamma makes it, shared_pow_table).
void encode_display_row(const float* linear, int cols, int y, std::int64_t frame_index, const EncodingParams& p,
                        int bits, void* code_row);

}  // namespace eyestream::retina
