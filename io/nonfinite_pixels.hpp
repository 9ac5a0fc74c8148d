// Counting the pixels of a float RGB image that hold a NaN or an infinity.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

namespace eyestream::io {

// Pixels of `pixels` interleaved RGB floats with any NaN or infinite
// channel (an exponent of all ones, tested by bits: the loop vectorises).
int nonfinite_in_row(const float* rgb, int pixels);

// The same over every row of a CV_32FC3 image, on the calling thread: a
// source counts a band of rows just decoded, while it is still in cache.
std::int64_t nonfinite_pixels(const cv::Mat& rgb);

}  // namespace eyestream::io
