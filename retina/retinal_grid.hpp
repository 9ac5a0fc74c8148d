// The grid of retina sites on which photoreceptor state lives: fixed to the
// retina, centred on the fovea (docs/model.md). Each step the scene is sampled
// into it at retina = scene - gaze; afterimage maps are drawn back to the
// display at the current gaze. The state itself is never resampled, so an
// afterimage neither blurs nor drifts as the gaze moves.
#pragma once

#include <memory>
#include <opencv2/core.hpp>

#include "retina/area_reduction.hpp"

namespace eyestream::retina {

// Extent: the grid spans twice the frame in each direction around the
// fovea, so every frame pixel has a site for any gaze inside the frame.
// Resolution: `sites_per_pixel` in (0, 1]: 1 is one site per frame pixel
// (reference); 0.5 halves each direction (afterimages are soft; a quarter
// of the cost).
class RetinalGrid {
 public:
  RetinalGrid(int frame_width, int frame_height, double sites_per_pixel);

  cv::Size size() const { return size_; }
  double sites_per_pixel() const { return scale_; }

  // Samples `scene` (CV_32FC3 or CV_64FC3, frame-sized) into the grid for a
  // gaze at (gaze_x, gaze_y) frame pixels (origin at the top-left corner).
  // The scene is area-averaged to the grid's resolution first, so a light
  // smaller than a site still delivers its energy. Sites that see outside
  // the frame see `outside`.
  cv::Mat sample(const cv::Mat& scene, double gaze_x, double gaze_y, const cv::Scalar& outside) const {
    return sample_reduced(reduce(scene), gaze_x, gaze_y, outside);
  }
  // The same in two parts, for several gazes on one frame: the frame
  // averaged down to the grid's resolution (once), then sampled.
  cv::Mat reduce(const cv::Mat& scene) const;
  // The size reduce() gives.
  cv::Size reduced_size() const;
  cv::Mat sample_reduced(const cv::Mat& reduced, double gaze_x, double gaze_y, const cv::Scalar& outside) const;

  // Draws a grid map back to a frame-sized image for a gaze at (gaze_x,
  // gaze_y), bilinearly. Frame pixels beyond the grid get `outside`.
  cv::Mat draw(const cv::Mat& map, double gaze_x, double gaze_y, const cv::Scalar& outside) const;
  // The same for a frame whose pixels see the sites `sites` (CV_32FC2, the
  // output's size; coordinates in `map`, centres at integers: `map` may be
  // a region of the grid, its sites then relative to the region).
  cv::Mat draw_at(const cv::Mat& map, const cv::Mat& sites, const cv::Scalar& outside) const;
  // The fovea in site coordinates.
  cv::Point2d fovea() const { return {centre_x_, centre_y_}; }

  // Gaussian fall-off exp(-e^2 / 2 sigma^2) of each site's eccentricity e
  // (frame pixels from the fovea), CV_32F; all ones for sigma_px <= 0.
  cv::Mat foveal_falloff(double sigma_px) const;

 private:
  int frame_width_, frame_height_;
  double scale_;
  cv::Size size_;
  double centre_x_, centre_y_;  // fovea, in site coordinates
  std::shared_ptr<const AreaReduction> reduction_;  // the frame to reduced_size(), if smaller
};

}  // namespace eyestream::retina
