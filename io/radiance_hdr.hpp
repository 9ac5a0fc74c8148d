// Radiance RGBE pictures (.hdr, Ward 1991): the header's lines up to an
// empty one, the resolution line "-Y height +X width" (rows top to bottom,
// the orientation nearly every writer uses; others are refused), then the
// scanlines, flat or in the adaptive run-length form (each of the four
// components in runs). OpenCV's reader, which this replaced, took a file
// as flat from the first flat scanline on; this one decides for each
// scanline by its marker, which gives the same pixels for every file a
// writer makes. A pixel's value is
// mantissa x 2^(exponent - 136), the format's definition; exponent 0 is
// black.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

namespace eyestream::io {

// The picture as CV_32FC3 (R, G, B), in the file's units (the caller
// scales to cd/m^2). InputError naming the file, and the scanline where
// the data is damaged, when it cannot be read; larger than `max_pixels`:
// refused before decoding.
cv::Mat read_radiance_hdr(const std::string& path, std::int64_t max_pixels = std::int64_t(1) << 31);

// The size the file's header declares, read without its pixels (the same
// checks of the header as read_radiance_hdr's).
cv::Size radiance_hdr_size(const std::string& path);

}  // namespace eyestream::io
