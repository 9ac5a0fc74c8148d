// The angle plane's splat of a frame (FrameProjection::to_plane_flux): each
// frame pixel's value spread bilinearly onto the four plane pixels around
// its fixed plane position, summed, times a per-plane-pixel factor.
//
// The plane is made in blocks of plane rows, one task each, so that every
// plane pixel sums its frame pixels in one order (frame rows, then
// columns) whatever the thread count. A frame row reaches a block along
// one or two runs of its pixels (a rectilinear frame's rows curve on the
// plane); the runs are found once, when the positions are fixed, so a
// block reads only the pixels that land on it: scanning every row a block
// might reach cost 19 ms a 1080p frame, most of it pixels that land
// elsewhere (docs/performance.md).
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace eyestream::pipeline {

class FixedSplat {
 public:
  // Frame pixel centres at plane positions `positions` (CV_32FC2, >= 0,
  // plane pixel centres at integer + 0.5) onto a `plane`-sized image.
  FixedSplat(const cv::Mat& positions, cv::Size plane);

  // out (CV_32FC3, plane-sized) = the splat of `frame` (CV_32FC3) times
  // `factor` (CV_32F, plane-sized).
  void apply(const cv::Mat& frame, const cv::Mat& factor, cv::Mat& out) const;

 private:
  struct Run {
    int y, x0, x1;  // frame row y, columns [x0, x1)
  };
  cv::Mat positions_;
  cv::Size plane_;
  std::vector<Run> runs_;          // block by block, each block's in frame order
  std::vector<size_t> first_run_;  // block b's runs are [first_run_[b], first_run_[b + 1])
};

}  // namespace eyestream::pipeline
