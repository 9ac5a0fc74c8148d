// Cheap whole-frame checks.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

namespace eyestream::pipeline {

// Pixels of a CV_32FC3 frame with any NaN or infinite channel.
std::int64_t count_nonfinite(const cv::Mat& rgb);

// A copy of a CV_32FC3 frame with every pixel that has a non-finite
// channel set to black.
cv::Mat finite_copy(const cv::Mat& rgb);

}  // namespace eyestream::pipeline
