#include "retina/retinal_grid.hpp"

#include "retina/parallel_fill.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace eyestream::retina {

RetinalGrid::RetinalGrid(int frame_width, int frame_height, double sites_per_pixel)
    : frame_width_(frame_width), frame_height_(frame_height), scale_(sites_per_pixel) {
  CV_Assert(sites_per_pixel > 0 && sites_per_pixel <= 1);
  size_ = cv::Size(int(std::ceil(2.0 * frame_width * scale_)) + 3, int(std::ceil(2.0 * frame_height * scale_)) + 3);
  centre_x_ = (size_.width - 1) / 2.0;
  centre_y_ = (size_.height - 1) / 2.0;
  if (scale_ < 1.0) reduction_ = std::make_shared<const AreaReduction>(cv::Size(frame_width, frame_height), reduced_size());
}

cv::Size RetinalGrid::reduced_size() const {
  if (scale_ >= 1.0) return {frame_width_, frame_height_};
  return {std::max(1, int(std::lround(frame_width_ * scale_))), std::max(1, int(std::lround(frame_height_ * scale_)))};
}

cv::Mat RetinalGrid::reduce(const cv::Mat& scene) const {
  CV_Assert(scene.cols == frame_width_ && scene.rows == frame_height_);
  if (scale_ >= 1.0) return scene;
  cv::Mat source;
  reduction_->apply(scene, source);
  return source;
}

cv::Mat RetinalGrid::sample_reduced(const cv::Mat& source, double gaze_x, double gaze_y,
                                    const cv::Scalar& outside) const {
  const double sx = double(frame_width_) / source.cols, sy = double(frame_height_) / source.rows;  // frame px per source px
  // Site u sees the frame point X = gaze_x + (u - centre_x) / scale (corner
  // origin), i.e. source pixel index X / sx - 0.5.
  const double ax = 1.0 / (scale_ * sx), ay = 1.0 / (scale_ * sy);
  const cv::Matx23d m(ax, 0, (gaze_x - centre_x_ / scale_) / sx - 0.5, 0, ay, (gaze_y - centre_y_ / scale_) / sy - 0.5);
  cv::Mat out;
  cv::warpAffine(source, out, m, size_, cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT, outside);
  return out;
}

cv::Mat RetinalGrid::draw(const cv::Mat& map, double gaze_x, double gaze_y, const cv::Scalar& outside) const {
  CV_Assert(map.size() == size_);
  // Frame pixel i has its centre at X = i + 0.5, seen by site centre_x + scale (X - gaze_x).
  const cv::Matx23d m(scale_, 0, centre_x_ + scale_ * (0.5 - gaze_x), 0, scale_, centre_y_ + scale_ * (0.5 - gaze_y));
  cv::Mat out;
  cv::warpAffine(map, out, m, cv::Size(frame_width_, frame_height_), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                 cv::BORDER_CONSTANT, outside);
  return out;
}

cv::Mat RetinalGrid::draw_at(const cv::Mat& map, const cv::Mat& sites, const cv::Scalar& outside) const {
  cv::Mat out;
  cv::remap(map, out, sites, cv::Mat(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, outside);
  return out;
}

cv::Mat RetinalGrid::foveal_falloff(double sigma_px) const {
  if (!(sigma_px > 0)) return filled_in_parallel(size_, CV_32F, cv::Scalar(1.0));
  cv::Mat w(size_, CV_32F);  // every value written below, rows in parallel
  cv::parallel_for_(cv::Range(0, size_.height), [&](const cv::Range& rows) {
    for (int v = rows.start; v < rows.end; ++v)
      for (int u = 0; u < size_.width; ++u) {
        const double e = std::hypot(u - centre_x_, v - centre_y_) / scale_;
        w.at<float>(v, u) = float(std::exp(-e * e / (2.0 * sigma_px * sigma_px)));
      }
  });
  return w;
}

}  // namespace eyestream::retina
