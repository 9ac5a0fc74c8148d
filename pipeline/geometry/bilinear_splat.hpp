// An image carried onto a target by a bilinear splat: each source pixel's
// value shared among the four target pixels around its position, and each
// target pixel the normalised mean of what lands on it (the frame
// projection's to_plane_mean and splat, and its plane's coverage). Made in
// blocks of target rows, each scanning only the source rows that reach
// it, so every sum takes its terms in one order whatever the thread count:
// the image's, row after row, each row's pixels from the left.
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::pipeline {

// A target position: t = pos * k + offset (pixel centres at integers).
struct SplatAffine {
  double kx = 1, ky = 1, offset = 0;
};

// `image` (CV_32FC1, CV_32FC3 or CV_64FC3) splatted at `positions`
// (CV_32FC2, the image's size) mapped by `a` onto a `size` target: each
// target pixel the mean of the shares that land on it, times
// `multiplier` (CV_32F, target-sized) when given, `outside` where nothing
// lands.
cv::Mat bilinear_splat(const cv::Mat& image, const cv::Mat& positions, SplatAffine a, cv::Size size,
                       const cv::Scalar& outside, const cv::Mat& multiplier);

}  // namespace eyestream::pipeline
