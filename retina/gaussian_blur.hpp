// Gaussian blur of float images (any channel count), borders replicated:
// the kernel OpenCV's GaussianBlur uses for floats (8 sigma + 1 taps), run
// as a horizontal and a vertical sweep over stripes of rows shared among
// threads. OpenCV's own float filter runs on one thread and copies every
// row into a bordered buffer; this one vectorises over the interleaved
// samples and needs no copy. The result does not depend on the thread count.
#pragma once

#include <functional>
#include <opencv2/core.hpp>

namespace eyestream::retina {

// dst = src blurred by sigma px each way (src and dst may be the same).
// `source_row_read`, when given, is called once for every row of src, on
// the thread that has just read it (while it is in cache), in no set order
// across threads; it must not write to src.
void gaussian_blur(const cv::Mat& src, cv::Mat& dst, double sigma,
                   const std::function<void(int row)>& source_row_read = {});

}  // namespace eyestream::retina
