// Writes a generated scene as DIR/frames/%05d.exr (half float, with
// whiteLuminance and framesPerSecond), DIR/gaze.csv and, for scenes with a
// visibility target, DIR/target/%05d.png (8-bit masks, 255 on the target;
// `eyestream run --target-mask DIR/target`).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "io/gaze_sample.hpp"
#include "io/staged_file.hpp"

namespace eyestream::samples {

class SceneWriter {
 public:
  // Pixel values are stored as L / white_luminance_cd_m2, so half floats
  // (largest 65504) hold up to 65504 * white_luminance_cd_m2 cd/m^2.
  SceneWriter(const std::string& out_dir, double fps, double white_luminance_cd_m2);
  // `rgb` is linear Rec.709 in cd/m^2 (CV_32FC3); `target_mask` (CV_8U,
  // optional; give one with every frame or with none) marks the target.
  void add_frame(const cv::Mat& rgb, const cv::Mat& target_mask = cv::Mat());
  // Writes the gaze log and moves every file into place.
  void finish(const std::vector<io::GazeSample>& gaze);

 private:
  std::string dir_;
  double fps_, white_;
  std::vector<io::StagedFile> files_;
  std::int64_t frames_ = 0;
  std::vector<bool> masked_;  // whether frame k came with a mask
};

}  // namespace eyestream::samples
