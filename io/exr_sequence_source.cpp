#include "io/exr_sequence_source.hpp"

#include <optional>

#include "io/error.hpp"
#include "io/exr_file.hpp"
#include "io/nonfinite_pixels.hpp"
#include "io/primaries.hpp"
#include "io/staged_file.hpp"

namespace eyestream::io {

ExrSequenceSource::ExrSequenceSource(const std::string& input, const ExrSequenceOptions& options)
    : options_(options), entries_(list_sequence(input, {".exr"}, options.skip_missing)) {
  for (const SequenceEntry& e : entries_) protect_input(e.path);
  std::int64_t nonfinite = 0;
  ExrImage probe = read(entries_.front(), &nonfinite);
  double fps =
      options_.frames_per_second.value_or(probe.frames_per_second.value_or(options_.default_frames_per_second));
  if (!(fps > 0)) throw UsageError("--fps: frame rate must be positive");
  info_.width = probe.rgb.cols;
  info_.height = probe.rgb.rows;
  info_.frames_per_second = fps;
  info_.frame_count = std::int64_t(entries_.size());
  info_.description = "EXR sequence, " + std::to_string(entries_.size()) + " frames, " + probe.channels +
                      (probe.layer.empty() ? "" : " of layer " + probe.layer);
  channels_ = probe.channels;
  first_ = frame_from(std::move(probe), nonfinite, entries_.front(), 0);  // the probe is the first frame: read once
}

SceneFrame ExrSequenceSource::decode(const SequenceEntry& entry, std::int64_t index) const {
  std::int64_t nonfinite = 0;
  ExrImage image = read(entry, &nonfinite);
  return frame_from(std::move(image), nonfinite, entry, index);
}

ExrImage ExrSequenceSource::read(const SequenceEntry& entry, std::int64_t* nonfinite) const {
  *nonfinite = 0;
  const auto to_rec709 = [](const ExrImage& image) {
    return image.chromaticities ? to_rec709_matrix(*image.chromaticities) : cv::Matx33d::eye();
  };
  const auto finish = [&](const ExrImage& image, cv::Mat& rows) {
    const double scale = options_.scale.value_or(image.white_luminance.value_or(1.0));
    if (scale != 1.0) rows *= scale;
    *nonfinite += nonfinite_pixels(rows);
  };
  // Most files are Rec.709: each band is scaled and counted as it is
  // decoded. Other primaries take the whole image through the matrix
  // first, as one call: cv::transform's vector and scalar paths round
  // differently, so bands would change the last bit of the pixels at
  // each band's end.
  std::optional<bool> banded;  // decided once, at the first band (the header is read by then)
  ExrImage image = read_exr(entry.path, options_.max_pixels, options_.layer, [&](const ExrImage& im, cv::Mat rows) {
    if (!banded) banded = is_identity(to_rec709(im));
    if (*banded) finish(im, rows);
  });
  if (!banded.value_or(false)) {
    apply_matrix(image.rgb, to_rec709(image));
    finish(image, image.rgb);
  }
  return image;
}

SceneFrame ExrSequenceSource::frame_from(ExrImage image, std::int64_t nonfinite, const SequenceEntry& entry,
                                         std::int64_t index) const {
  if (index > 0 && (image.rgb.cols != info_.width || image.rgb.rows != info_.height))
    throw InputError(entry.path + ": frame " + std::to_string(index) + " is " + std::to_string(image.rgb.cols) + "x" +
                     std::to_string(image.rgb.rows) + ", the sequence began at " + std::to_string(info_.width) + "x" +
                     std::to_string(info_.height));
  if (index > 0 && image.channels != channels_)
    throw InputError(entry.path + ": frame " + std::to_string(index) + " has channels " + image.channels +
                     ", the sequence began with " + channels_);
  SceneFrame frame;
  frame.rgb = std::move(image.rgb);
  frame.nonfinite = nonfinite;
  frame.index = index;
  frame.time_s = sequence_time(entries_, size_t(index), info_.frames_per_second);
  frame.source = entry.path;
  return frame;
}

std::optional<SceneFrame> ExrSequenceSource::next() {
  if (position_ >= entries_.size()) return std::nullopt;
  std::int64_t index = std::int64_t(position_);
  const SequenceEntry& entry = entries_[position_++];
  if (first_) {
    SceneFrame f = std::move(*first_);
    first_.reset();
    return f;
  }
  return decode(entry, index);
}

std::optional<double> ExrSequenceSource::time_of(std::int64_t index) const {
  if (index < 0 || size_t(index) >= entries_.size()) return std::nullopt;
  return sequence_time(entries_, size_t(index), info_.frames_per_second);
}

}  // namespace eyestream::io
