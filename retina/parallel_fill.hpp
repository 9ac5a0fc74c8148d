// An image of one value, its rows filled by the threads in parallel. A
// fresh image's pages are zeroed by the kernel when first touched (about 2
// ms a MB on the virtual machine the project measures on,
// docs/performance.md); cv::Mat's own fills (zeros, a Scalar, setTo) take
// every page on the calling thread. The values are those of cv::Mat's fill.
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::retina {

cv::Mat filled_in_parallel(cv::Size size, int type, const cv::Scalar& value);

}  // namespace eyestream::retina
