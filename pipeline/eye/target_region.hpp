// The scene's visibility target (a pedestrian, a road marking): where it is
// in each frame, and its luminance against its surround, for the report's
// luminance contrast with and without the veil.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

namespace eyestream::pipeline {

// Mean scene luminance over a target and over its surround: the pixels
// within r of the target but outside it, r the smaller side of the
// target's bounding box (a ring as wide as the target), clipped to the
// frame. (x, y) is the target's centroid in frame pixels.
struct TargetLuminance {
  double target_cd_m2 = 0.0, background_cd_m2 = 0.0;
  double x = 0.0, y = 0.0;
};

// `luminance` CV_32F cd/m^2; `mask` CV_8U of the same size, nonzero on the
// target. Nothing when the mask is empty, marks nothing, or leaves no
// surround.
std::optional<TargetLuminance> measure_target(const cv::Mat& luminance, const cv::Mat& mask);

// Luminance contrast C = (L_t - L_b) / L_b, and with a veil L_v added to
// both (the veil shifts both luminances alike): (L_t - L_b) / (L_b + L_v).
double luminance_contrast(double target_cd_m2, double background_cd_m2, double veil_cd_m2 = 0.0);

// Where the target is: `--target X,Y,W,H` (a rectangle in frame pixels, the
// same in every frame) or `--target-mask` (one mask image for every frame,
// or a numbered sequence or folder of them, one per frame in order; pixels
// above half scale mark the target).
class TargetRegion {
 public:
  // Both empty: no target. Errors: UsageError for a malformed or
  // out-of-frame rectangle or both given, InputError for mask files.
  TargetRegion(const std::string& rectangle, const std::string& mask, cv::Size frame);
  bool enabled() const { return !rect_.empty() || !masks_.empty(); }
  // The mask of frame `index` (0-based position in the input), CV_8U;
  // empty without a target. InputError naming the file when a mask is
  // missing, unreadable or of another size.
  cv::Mat mask(std::int64_t index) const;

 private:
  cv::Size frame_;
  cv::Rect rect_;
  std::vector<std::string> masks_;
};

}  // namespace eyestream::pipeline
