// The angle plane's splat of a frame (FrameProjection::to_plane_flux): each
// frame pixel's value spread bilinearly onto the four plane pixels around
// its fixed plane position, summed, times a per-plane-pixel factor.
//
// The plane is made in blocks of plane rows, one task each, so that every
// plane pixel sums its frame pixels in one order (frame rows, then
// columns) whatever the thread count. A frame row reaches a block along
// one or two runs of its pixels (a rectilinear frame's rows curve on the
// plane); the runs are found once, when the positions are fixed, so a
// block reads only the pixels that land on it, not every pixel of every
// row that might reach it (docs/performance.md). A pixel's three channels
// are held as one four-float vector: each bilinear share is one multiply
// and one add.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace eyestream::pipeline {

class FixedSplat {
 public:
  // Frame pixel centres at plane positions `positions` (CV_32FC2, plane
  // pixel centres at integer + 0.5; x in [-0.5, plane width + 0.5), y in
  // [-0.5, 1e8): a footprint reaching beyond the plane's last row is cut there)
  // onto a `plane`-sized image. The positions are shared, not copied: they
  // must not change while the splat is used.
  FixedSplat(const cv::Mat& positions, cv::Size plane);

  // out (CV_32FC3, plane-sized) = the splat of `frame` (CV_32FC3) times
  // `factor` (CV_32F, plane-sized).
  void apply(const cv::Mat& frame, const cv::Mat& factor, cv::Mat& out) const;
  // out (CV_32F, plane-sized) = the sum of the weights landing on each
  // plane pixel: channel 0 of apply() of a frame of ones by a factor of 1,
  // bit for bit, without either image.
  void weight_sums(cv::Mat& out) const;

 private:
  // apply() (kOnes false), or weight_sums() (a frame of ones, no factor,
  // one channel out).
  template <bool kOnes>
  void splat(const cv::Mat* frame, const cv::Mat* factor, cv::Mat& out) const;
  struct Run {
    int y, x0, x1;  // frame row y, columns [x0, x1)
  };
  cv::Mat positions_;
  cv::Size plane_;
  std::vector<Run> runs_;          // block by block, each block's in frame order
  std::vector<size_t> first_run_;  // block b's runs are [first_run_[b], first_run_[b + 1])
};

}  // namespace eyestream::pipeline
