#include "pipeline/eye/target_region.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "io/error.hpp"
#include "io/float_tiff.hpp"
#include "io/frame_sequence.hpp"
#include "io/png_file.hpp"
#include "io/staged_file.hpp"

namespace eyestream::pipeline {

std::optional<TargetLuminance> measure_target(const cv::Mat& luminance, const cv::Mat& mask) {
  if (mask.empty()) return std::nullopt;
  const cv::Rect box = cv::boundingRect(mask);
  if (box.empty()) return std::nullopt;
  const int r = std::max(1, std::min(box.width, box.height));
  cv::Mat grown;
  cv::dilate(mask, grown, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * r + 1, 2 * r + 1)));
  cv::Mat ring = grown & ~(mask != 0);
  if (cv::countNonZero(ring) == 0) return std::nullopt;
  const cv::Moments m = cv::moments(mask != 0, true);
  TargetLuminance t;
  t.target_cd_m2 = cv::mean(luminance, mask)[0];
  t.background_cd_m2 = cv::mean(luminance, ring)[0];
  t.x = m.m10 / m.m00 + 0.5;
  t.y = m.m01 / m.m00 + 0.5;
  return t;
}

double luminance_contrast(double target_cd_m2, double background_cd_m2, double veil_cd_m2) {
  return (target_cd_m2 - background_cd_m2) / (background_cd_m2 + veil_cd_m2);
}

namespace {

cv::Rect parse_rectangle(const std::string& text, cv::Size frame) {
  std::istringstream in(text);
  int v[4];
  char comma;
  bool ok = bool(in >> v[0]);
  for (int i = 1; ok && i < 4; ++i) ok = (in >> comma >> v[i]) && comma == ',';
  if (!ok || !(in >> std::ws).eof())
    throw UsageError("--target '" + text + "': expected X,Y,W,H in frame pixels");
  const cv::Rect r(v[0], v[1], v[2], v[3]);
  if (r.width <= 0 || r.height <= 0 || (r & cv::Rect(cv::Point(), frame)) != r)
    throw UsageError("--target '" + text + "': the rectangle must be non-empty and inside the " +
                     std::to_string(frame.width) + "x" + std::to_string(frame.height) + " frame");
  return r;
}

}  // namespace

TargetRegion::TargetRegion(const std::string& rectangle, const std::string& mask, cv::Size frame) : frame_(frame) {
  if (!rectangle.empty() && !mask.empty()) throw UsageError("--target and --target-mask: give one of them");
  if (!rectangle.empty()) rect_ = parse_rectangle(rectangle, frame);
  if (!mask.empty())
    for (const io::SequenceEntry& e : io::list_sequence(mask, {".png", ".tif", ".tiff"}, false,
                                                              "a target mask is needed for every frame")) {
      const std::string ext = io::lower_extension(e.path);  // a single file is listed whatever its name
      if (ext != ".png" && ext != ".tif" && ext != ".tiff")
        throw InputError(e.path + ": target masks are read from PNG or TIFF files; convert it to one of them");
      masks_.push_back(e.path), io::protect_input(e.path);
    }
}

cv::Mat TargetRegion::mask(std::int64_t index) const {
  if (!rect_.empty()) {
    cv::Mat m = cv::Mat::zeros(frame_, CV_8U);
    m(rect_).setTo(255);
    return m;
  }
  if (masks_.empty()) return cv::Mat();
  if (masks_.size() > 1 && index >= std::int64_t(masks_.size()))
    throw InputError("--target-mask: no mask for frame " + std::to_string(index) + " (the sequence has " +
                     std::to_string(masks_.size()) + ")");
  const std::string& path = masks_[masks_.size() == 1 ? 0 : index];
  // A PNG's or TIFF's codes, colour made grey, as 8 bits (16-bit codes by
  // their high byte, as OpenCV's grey reading gave them).
  cv::Mat grey;
  try {
    // A mask is the frames' size: up to four times it is read (and then
    // refused by its size, below); more, refused before decoding.
    const std::int64_t most = std::max<std::int64_t>(4 * std::int64_t(frame_.area()), 1'000'000);
    const std::string ext = io::lower_extension(path);
    if (ext == ".tif" || ext == ".tiff") {
      cv::cvtColor(io::read_code_tiff(path, most), grey, cv::COLOR_RGB2GRAY);
      grey.convertTo(grey, CV_8U, 255.0);
    } else {
      grey = io::read_png(path, most);
      if (grey.channels() == 3) cv::cvtColor(grey, grey, cv::COLOR_RGB2GRAY);
      if (grey.depth() == CV_16U) {
        cv::Mat high(grey.size(), CV_8U);
        for (int y = 0; y < grey.rows; ++y)
          for (int x = 0; x < grey.cols; ++x) high.at<unsigned char>(y, x) = grey.at<std::uint16_t>(y, x) >> 8;
        grey = high;
      }
    }
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + " (reading the target mask)");
  }
  if (grey.size() != frame_)
    throw InputError(path + ": target mask is " + std::to_string(grey.cols) + "x" + std::to_string(grey.rows) +
                     ", the frames " + std::to_string(frame_.width) + "x" + std::to_string(frame_.height));
  return grey > 127;
}

}  // namespace eyestream::pipeline
