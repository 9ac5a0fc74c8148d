// Floating-point TIFF stills through libtiff (Debian's libtiff-dev): 32- and
// 16-bit (half) IEEE samples, grey, grey + alpha, RGB or RGBA, strips or
// tiles, interleaved or planar, any compression libtiff decodes. OpenCV's
// reader refuses half floats and extra (alpha) samples and prints its own
// lines on stderr before failing, so eyestream reads these itself; and,
// since OpenCV's image codecs are no longer linked, 8- and 16-bit display
// frames for `eyestream compare`.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

namespace eyestream::io {

// The first image of the file as linear RGB, CV_32FC3 (R, G, B; grey is
// copied to the three; alpha is dropped). InputError naming the file and
// what it holds when the file is not a floating-point TIFF of that kind.
// Larger than `max_pixels`: refused before decoding.
cv::Mat read_float_tiff(const std::string& path, std::int64_t max_pixels = std::int64_t(1) << 31);

// A display frame's codes as CV_32FC3 over the codes' largest value (0 to
// 1): 16-bit grey or RGB samples in the layouts above, and 8 bits or fewer
// in any photometric interpretation (palette, grey either way round, one
// bit a pixel, YCbCr, CMYK) through libtiff's RGBA conversion, as OpenCV
// read them. Larger than `max_pixels`: refused before decoding.
cv::Mat read_code_tiff(const std::string& path, std::int64_t max_pixels);

}  // namespace eyestream::io
