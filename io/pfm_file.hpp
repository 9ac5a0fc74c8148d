// Portable float maps (.pfm): "PF" (RGB) or "Pf" (grey), the width and
// height, then a scale whose sign gives the byte order (negative: little
// endian) and whose magnitude divides the values (as OpenCV's reader did:
// each times the float 1 / |scale|),
// then 32-bit floats, rows from the bottom up.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

namespace eyestream::io {

// The picture as CV_32FC3 (R, G, B; grey copied to the three).
// InputError naming the file when it cannot be read; larger than
// `max_pixels`: refused before decoding.
cv::Mat read_pfm(const std::string& path, std::int64_t max_pixels = std::int64_t(1) << 31);

// The size the file's header declares, read without its pixels (the same
// checks of the header as read_pfm's).
cv::Size pfm_size(const std::string& path);

}  // namespace eyestream::io
