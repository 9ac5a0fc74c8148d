// Mean log10 luminance over square patches of a frame in O(1) per query:
// the adaptation target around the gaze (seed 001 sec. 2.1; MODEL.md 2.1).
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::retina {

class LogLuminanceField {
 public:
  // `rgb` is linear Rec.709 in cd/m^2. Luminance below floor_cd_m2 (and
  // non-finite or negative luminance) counts as floor_cd_m2.
  LogLuminanceField(const cv::Mat& rgb, double floor_cd_m2);

  // Mean of log10 luminance over the square of side 2*half_size_px centred at
  // (x, y) in frame pixels (origin at the top-left corner of the top-left
  // pixel). The part of the square outside the frame counts as
  // surround_log (log10 cd/m^2).
  double patch_mean(double x, double y, double half_size_px, double surround_log) const;

 private:
  cv::Mat integral_;  // CV_64F, (rows+1) x (cols+1)
};

}  // namespace eyestream::retina
