// A picture written as a PNG file that appears only when complete.
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <vector>

#include "io/staged_file.hpp"

namespace eyestream::io {

// `bgr` (CV_8UC3, CV_16UC3 or one channel) as PNG bytes carrying gAMA
// (the encoding's exponent: code = light^gamma) and cHRM (Rec.709
// primaries, D65) chunks, so viewers know the colours; empty if encoding
// failed.
std::vector<unsigned char> encode_png(const cv::Mat& bgr, double gamma = 1.0 / 2.2);

// Encodes `bgr` (CV_8UC3, or CV_8UC1) as PNG, writes it under a temporary
// name and renames it to `path`; OutputError naming `path` on failure.
void write_png(const std::filesystem::path& path, const cv::Mat& bgr);

// The same, left under its temporary name for the caller to commit.
StagedFile stage_png(const std::filesystem::path& path, const cv::Mat& bgr);

}  // namespace eyestream::io
