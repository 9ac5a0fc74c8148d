// A three-channel map whose channels are all equal, held as one channel:
// a third of the memory and of the reads every frame (the glare's in-frame
// shares, GlareStage).
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::pipeline {

// `map` (CV_32FC3, finite) as one channel (CV_32F, channel 0's values bit
// for bit) when every pixel's three values compare equal (+0 and -0
// alike), else `map` itself. Stops at the first pixel whose values
// differ, and makes no per-channel copies.
cv::Mat one_channel_if_grey(const cv::Mat& map);

}  // namespace eyestream::pipeline
