// A picture written as a PNG file that appears only when complete.
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>

#include "io/staged_file.hpp"

namespace eyestream::io {

// Encodes `bgr` (CV_8UC3, or CV_8UC1) as PNG, writes it under a temporary
// name and renames it to `path`; OutputError naming `path` on failure.
void write_png(const std::filesystem::path& path, const cv::Mat& bgr);

// The same, left under its temporary name for the caller to commit.
StagedFile stage_png(const std::filesystem::path& path, const cv::Mat& bgr);

}  // namespace eyestream::io
