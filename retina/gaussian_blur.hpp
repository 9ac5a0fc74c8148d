// Gaussian blur of float images (any channel count), borders replicated:
// the kernel OpenCV's GaussianBlur uses for floats (8 sigma + 1 taps), run
// as a horizontal and a vertical sweep over stripes of rows shared among
// threads. OpenCV's own float filter runs on one thread and copies every
// row into a bordered buffer; this one vectorises over the interleaved
// samples and needs no copy. The result does not depend on the thread count.
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::retina {

// dst = src blurred by sigma px each way (src and dst may be the same).
void gaussian_blur(const cv::Mat& src, cv::Mat& dst, double sigma);

}  // namespace eyestream::retina
