// Reading and writing single OpenEXR images with the standard attributes
// eyestream uses (whiteLuminance, chromaticities, framesPerSecond).
#pragma once

#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/primaries.hpp"

namespace eyestream::io {

struct ExrImage {
  cv::Mat rgb;                            // CV_32FC3, file's own primaries
  std::optional<double> white_luminance;  // cd/m^2 of RGB = (1,1,1)
  std::optional<Chromaticities> chromaticities;
  std::optional<double> frames_per_second;
  std::string channels;  // "RGB", "RGBA" or "Y"
  std::string layer;     // the layer read ("" the root, "ViewLayer.Combined" ...)
};

// Reads RGB, RGBA (alpha ignored) or luminance-only (Y) EXR files, half or
// float. Refuses (InputError, naming the file) a file that is unreadable,
// truncated, lacks those channels, or whose data window exceeds max_pixels
// (checked from the header before any pixel memory is allocated).
// Layered files (Blender's multilayer "ViewLayer.Combined.R", ...): `layer`
// names the one to read; without it, the root R,G,B, else the beauty pass
// (a layer ending in Combined, beauty or RGBA), else the only colour layer;
// anything else is refused listing the layers.
// `on_rows`, when given, is called with each band of rows as soon as it is
// decoded (a view into image.rgb; the other fields are set by then), in
// order from the top: work on the pixels while they are in cache.
using ExrRowsHook = std::function<void(const ExrImage& image, cv::Mat rows)>;
ExrImage read_exr(const std::string& path, std::int64_t max_pixels, const std::string& layer = "",
                  const ExrRowsHook& on_rows = {});

// OpenEXR's lossless compressions. On float output, ZIP (the default)
// saves about a seventh of the bytes and writes several times slower than
// none (docs/usage.md gives the figures).
enum class ExrCompression { kNone, kRle, kZips, kZip, kPiz };

// The names --exr-compression takes (none, rle, zips, zip, piz); anything
// else is a UsageError naming it.
ExrCompression exr_compression_named(const std::string& name);

struct ExrWriteOptions {
  bool half = true;
  std::optional<double> white_luminance;
  std::optional<double> frames_per_second;
  ExrCompression compression = ExrCompression::kZip;
};

// Writes a CV_32FC3 RGB image to `path`. The caller makes the file atomic
// (see StagedFile) when it matters.
void write_exr(const std::string& path, const cv::Mat& rgb, const ExrWriteOptions& options);

// Writes named single-channel float planes (CV_32F, one size) to one EXR
// file, e.g. state maps for inspection.
void write_exr_channels(const std::string& path, const std::vector<std::pair<std::string, cv::Mat>>& planes);

}  // namespace eyestream::io
