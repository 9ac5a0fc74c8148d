// Writes a generated scene as DIR/frames/%05d.exr (half float, with
// whiteLuminance and framesPerSecond) and DIR/gaze.csv.
#pragma once

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
  // `rgb` is linear Rec.709 in cd/m^2 (CV_32FC3).
  void add_frame(const cv::Mat& rgb);
  // Writes the gaze log and moves every file into place.
  void finish(const std::vector<io::GazeSample>& gaze);

 private:
  std::string dir_;
  double fps_, white_;
  std::vector<io::StagedFile> files_;
};

}  // namespace eyestream::samples
