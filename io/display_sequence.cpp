#include "io/display_sequence.hpp"

#include <algorithm>
#include <filesystem>
#include <opencv2/imgproc.hpp>

#include "io/error.hpp"
#include "io/exr_file.hpp"
#include "io/float_tiff.hpp"
#include "io/png_file.hpp"
#include "io/staged_file.hpp"

namespace eyestream::io {

namespace {

const std::vector<std::string> kImageExtensions = {".png", ".exr", ".tif", ".tiff"};

bool is_image_path(const std::string& path) {
  if (std::filesystem::is_directory(path)) return true;
  const std::string ext = lower_extension(path);
  return std::find(kImageExtensions.begin(), kImageExtensions.end(), ext) != kImageExtensions.end();
}

bool is_exr(const std::string& path) { return lower_extension(path) == ".exr"; }

// A PNG (png_file.hpp) or TIFF (float_tiff.hpp) frame's codes over their
// largest value, R, G, B.
cv::Mat read_code_image(const std::string& path) {
  const std::string ext = lower_extension(path);
  constexpr std::int64_t kMostPixels = 400'000'000;  // as for EXR frames (below)
  if (ext == ".tif" || ext == ".tiff") return read_code_tiff(path, kMostPixels);
  const cv::Mat img = read_png(path, kMostPixels);
  cv::Mat rgb = img;
  if (img.channels() == 1) cv::cvtColor(img, rgb, cv::COLOR_GRAY2RGB);
  cv::Mat out;
  rgb.convertTo(out, CV_32FC3, img.depth() == CV_8U ? 1.0 / 255.0 : 1.0 / 65535.0);
  return out;
}

}  // namespace

DisplaySequence::DisplaySequence(const std::string& path, const std::string& layer) : path_(path), layer_(layer) {
  if (is_image_path(path)) {
    files_ = list_sequence(path, kImageExtensions, false, "compare pairs every frame: give both sequences whole");
    const bool exr = is_exr(files_.front().path);
    kind_ = exr ? Kind::kLinear : Kind::kCode;
    for (const SequenceEntry& e : files_) {
      protect_input(e.path);
      if (is_exr(e.path) != exr) throw InputError(path + ": mixes EXR and other images");
    }
  } else {
    if (!std::filesystem::is_regular_file(path)) throw InputError(path + ": no such file");
    protect_input(path);
    video_ = std::make_unique<VideoReader>(path);
    const std::string& transfer = video_->colour().transfer;
    if (transfer == "smpte2084" || transfer == "arib-std-b67") {
      video_.reset();
      hdr_ = std::make_unique<VideoSource>(path, VideoSourceOptions{});
      kind_ = Kind::kHdrLight;
    }
  }
}

std::int64_t DisplaySequence::frame_count() const {
  if (hdr_) return hdr_->info().frame_count;
  return video_ ? video_->frame_count() : std::int64_t(files_.size());
}

const char* DisplaySequence::kind_name() const {
  switch (kind_) {
    case Kind::kLinear: return "linear EXR";
    case Kind::kHdrLight: return "PQ/HLG video (light)";
    default: return "display-coded";
  }
}

std::optional<DisplayImage> DisplaySequence::next() {
  if (hdr_) {
    std::optional<SceneFrame> f = hdr_->next();
    if (!f) return std::nullopt;
    cv::Mat relative;
    f->rgb.convertTo(relative, CV_32FC3, 1.0 / kHdrReferenceWhite);
    return DisplayImage{relative, f->source, f->index};
  }
  if (video_) {
    std::optional<VideoFrame> f = video_->next();
    if (!f) return std::nullopt;
    return DisplayImage{f->rgb, path_ + " frame " + std::to_string(f->index), f->index};
  }
  if (position_ >= files_.size()) return std::nullopt;
  const SequenceEntry& entry = files_[position_++];
  if (kind_ == Kind::kLinear) return DisplayImage{read_exr(entry.path, 400'000'000, layer_).rgb, entry.path, entry.number};
  return DisplayImage{read_code_image(entry.path), entry.path, entry.number};
}

}  // namespace eyestream::io
