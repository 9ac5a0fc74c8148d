#include "io/float_image_source.hpp"

#include <algorithm>
#include <filesystem>
#include <opencv2/imgproc.hpp>

#include "io/error.hpp"
#include "io/float_tiff.hpp"
#include "io/float_image_header.hpp"
#include "io/pfm_file.hpp"
#include "io/radiance_hdr.hpp"
#include "io/staged_file.hpp"

namespace eyestream::io {

namespace {

const std::vector<std::string> kExtensions = {".hdr", ".pfm", ".tif", ".tiff"};

bool is_still_extension(const std::string& ext) {
  return std::find(kExtensions.begin(), kExtensions.end(), ext) != kExtensions.end();
}

}  // namespace

bool is_float_image_input(const std::string& input) {
  if (is_still_extension(lower_extension(input))) return true;
  if (!std::filesystem::is_directory(input)) return false;
  for (const auto& e : std::filesystem::directory_iterator(input)) {
    const std::string x = lower_extension(e.path().string());
    if (x == ".exr") return false;
    if (is_still_extension(x)) return true;
  }
  return false;
}

FloatImageSource::FloatImageSource(const std::string& input, const ExrSequenceOptions& o)
    : options_(o), entries_(list_sequence(input, kExtensions, o.skip_missing)) {
  for (const SequenceEntry& e : entries_) protect_input(e.path);
  info_.frames_per_second = o.frames_per_second.value_or(o.default_frames_per_second);
  if (!(info_.frames_per_second > 0)) throw UsageError("--fps: frame rate must be positive");
  info_.frame_count = std::int64_t(entries_.size());
  info_.description = std::to_string(entries_.size()) + " " + lower_extension(entries_.front().path) + " stills";
  first_ = next();  // sets the size; handed out first
}

std::optional<SceneFrame> FloatImageSource::next() {
  if (first_) {
    std::optional<SceneFrame> f = std::move(first_);
    first_.reset();
    return f;
  }
  if (position_ >= entries_.size()) return std::nullopt;
  const SequenceEntry& entry = entries_[position_];
  const std::int64_t index = std::int64_t(position_++);
  // The declared size is checked before the image is decoded.
  const cv::Size declared = float_image_size(entry.path);
  if (declared.width * std::int64_t(declared.height) > options_.max_pixels)
    throw InputError(entry.path + ": " + std::to_string(declared.width) + "x" + std::to_string(declared.height) +
                     " exceeds the limit of " + std::to_string(options_.max_pixels) + " pixels (--max-pixels)");
  // TIFF through libtiff (float_tiff.hpp), Radiance .hdr and PFM by their
  // own readers: each gives R, G, B.
  const std::string ext = lower_extension(entry.path);
  const cv::Mat image = ext == ".tif" || ext == ".tiff" ? read_float_tiff(entry.path, options_.max_pixels)
                        : ext == ".pfm"                 ? read_pfm(entry.path, options_.max_pixels)
                                                        : read_radiance_hdr(entry.path, options_.max_pixels);
  if (index == 0 && info_.width == 0) info_.width = image.cols, info_.height = image.rows;
  if (image.cols != info_.width || image.rows != info_.height)
    throw InputError(entry.path + ": frame " + std::to_string(index) + " is " + std::to_string(image.cols) + "x" +
                     std::to_string(image.rows) + ", the sequence began at " + std::to_string(info_.width) + "x" +
                     std::to_string(info_.height));
  SceneFrame f;
  f.rgb = image;
  const double scale = options_.scale.value_or(lower_extension(entry.path) == ".hdr" ? 179.0 : 1.0);
  if (scale != 1.0) f.rgb *= scale;
  f.index = index;
  f.time_s = sequence_time(entries_, size_t(index), info_.frames_per_second);
  f.source = entry.path;
  return f;
}

std::optional<double> FloatImageSource::time_of(std::int64_t index) const {
  if (index < 0 || size_t(index) >= entries_.size()) return std::nullopt;
  return sequence_time(entries_, size_t(index), info_.frames_per_second);
}

}  // namespace eyestream::io
