// PNG pictures through libpng: written with their colour tags and staged
// so that a file appears only when complete, and read for the target
// masks and compared frames. OpenCV's image codecs did this until
// 2026-12-06; their library brings about 70 others (GDAL and its
// formats) into every process: `eyestream --version` took 0.21 s with them
// and 0.10 s without (docs/performance.md).
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "io/staged_file.hpp"

namespace eyestream::io {

// `bgr` (CV_8U or CV_16U; three channels in OpenCV's blue-green-red order,
// or one) as PNG bytes carrying gAMA (the encoding's exponent: code =
// light^gamma) and cHRM (Rec.709 primaries, D65) chunks, so viewers know
// the colours. Compressed as OpenCV's encoder did (the Sub filter, zlib's
// fastest level, run-length strategy): the same bytes as before. Empty if
// encoding failed.
std::vector<unsigned char> encode_png(const cv::Mat& bgr, double gamma = 1.0 / 2.2);

// Encodes `bgr` as PNG, writes it under a temporary name and renames it to
// `path`; OutputError naming `path` on failure.
void write_png(const std::filesystem::path& path, const cv::Mat& bgr);

// The same, left under its temporary name for the caller to commit.
StagedFile stage_png(const std::filesystem::path& path, const cv::Mat& bgr);

// A PNG file's pixels as stored: CV_8U or CV_16U, one channel (grey) or
// three (R, G, B in that order); palettes and low bit depths expanded,
// alpha dropped, no gamma applied. Larger than `max_pixels`: refused
// before decoding. InputError naming the file when it cannot be read.
cv::Mat read_png(const std::string& path, std::int64_t max_pixels = std::int64_t(1) << 31);

}  // namespace eyestream::io
