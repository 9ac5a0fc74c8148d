// Mean luminance over patches of a frame: the adaptation target around the
// gaze, the log of the average luminance of a small patch (Jacobs et al.
// 2015, sec. 2.1), and the field luminance the pupil responds to. A frame
// is mostly asked for a few small patches, so each is summed directly (in
// double, row by row); a patch over kDirectSumPixels (a wide adaptation
// patch) is read from an integral image of the frame, made on first need.
// Not for concurrent use (the integral image and the mean are made lazily).
#pragma once

#include <functional>
#include <opencv2/core.hpp>

namespace eyestream::retina {

class LuminanceField {
 public:
  // `rgb` is linear Rec.709 in cd/m^2. Luminance below floor_cd_m2 (and
  // non-finite or negative luminance) counts as floor_cd_m2.
  // `weights` (CV_32F, frame-sized; empty: all equal) weigh the pixels in
  // frame_mean(): their solid angles, for a frame whose pixels do not all
  // subtend the same angle.
  LuminanceField(const cv::Mat& rgb, double floor_cd_m2, const cv::Mat& weights = cv::Mat());

  // log10 of the mean luminance over the square of side 2*half_size_px
  // centred at (x, y) in frame pixels (origin at the top-left corner of the
  // top-left pixel). The part of the square outside the frame counts as
  // surround_cd_m2. A patch half 1000 and half 1 cd/m^2 gives log10(500.5):
  // bright parts dominate, as they do for the eye.
  double patch_log_mean(double x, double y, double half_size_px, double surround_cd_m2) const {
    return patch_log_mean(x, y, half_size_px, half_size_px, surround_cd_m2);
  }
  // The same over a rectangle of half sides half_x_px and half_y_px.
  double patch_log_mean(double x, double y, double half_x_px, double half_y_px, double surround_cd_m2) const;

  // Mean luminance of the whole frame (cd/m^2), weighted as constructed.
  // Made on first call (most fields are read for patches only).
  double frame_mean() const;

  // The floored luminance itself (CV_32F, frame-sized), for others to read.
  const cv::Mat& luminance() const { return luminance_; }

 private:
  static constexpr double kDirectSumPixels = 65536;
  cv::Mat luminance_;  // CV_32F
  mutable cv::Mat integral_;  // CV_64F, (rows+1) x (cols+1); made when a patch is big
  cv::Mat weights_;  // as constructed
  mutable double mean_ = -1.0;  // < 0: not made yet
};

// The total of `weights` (0 when empty), for scene_means.
double sum_of_weights(const cv::Mat& weights);

// The geometric mean luminance (cd/m^2) of the band of width band_px along
// the frame's edge (the whole frame when the band covers it): what the
// world beyond the frame is taken to be. Geometric, so one bright light in
// the band does not light the whole surround. Luminance below the floor
// (and non-finite) counts as the floor, float(floor_cd_m2) as in the
// field's floored luminance; floor_cd_m2 must be positive. The logs are
// log_sum.hpp's (within a few units in the last place of the exact ones).
double edge_log_mean(const cv::Mat& rgb, double band_px, double floor_cd_m2);

// In one pass that keeps no luminance map: the mean, the value
// LuminanceField(rgb, floor_cd_m2, weights).frame_mean() has, bit for bit
// (the pupil's field on a frame whose own field is not otherwise read;
// `weight_total` is sum_of_weights(weights), unused when `weights` is
// empty), and the edge's geometric mean as edge_log_mean when band_px > 0
// (else edge is 0). also_per_row(y), when given, is called once for each row, on the
// pass's threads, right after the row is read: for another digest of the
// frame while its row is in cache (the glare stage's frame digest).
struct SceneMeans {
  double mean = 0.0, edge = 0.0;
};
SceneMeans scene_means(const cv::Mat& rgb, double floor_cd_m2, const cv::Mat& weights, double weight_total,
                       double band_px, const std::function<void(int)>& also_per_row = {});

}  // namespace eyestream::retina
