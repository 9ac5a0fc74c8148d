// The fixed-point maps cv::remap reads for bilinear sampling (CV_16SC2
// whole pixels, CV_16UC1 fraction indices), made from plane positions
// with pixel centres at integer + 0.5: what cv::convertMaps gives for the
// positions minus (0.5, 0.5), bit for bit, without making that shifted
// copy first (a frame-sized CV_32FC2 image, 17 MB at 1080p, each page's
// first touch a cost at set-up).
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::pipeline {

// map1 (CV_16SC2) and map2 (CV_16UC1), positions' size, from `positions`
// (CV_32FC2).
void remap_maps(const cv::Mat& positions, cv::Mat& map1, cv::Mat& map2);

}  // namespace eyestream::pipeline
