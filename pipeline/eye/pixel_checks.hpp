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

// `map` (CV_32FC3, finite) as one channel (CV_32F, channel 0's values bit
// for bit) when every pixel's three values compare equal (+0 and -0
// alike), else `map` itself. Stops at the first pixel whose values differ;
// a grey map costs one channel's copy, not three. (The glare's in-frame
// shares: a grey one takes a third of the memory and of the reads every
// frame.)
cv::Mat one_channel_if_grey(const cv::Mat& map);

}  // namespace eyestream::pipeline
