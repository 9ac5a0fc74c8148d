// An image halved each way by the mean of each 2 x 2 block: what
// cv::resize with INTER_AREA gives, bit for bit, made here in one
// row-parallel loop for three-channel float images of even size, a
// pixel's three values as one vector (OpenCV's plain loop there took 4.8
// ms of a `fast` 1080p frame, a loop over values here 2.1, timed in place;
// the compiler vectorised that loop only two floats wide). Odd sizes, whose last row or column OpenCV
// weighs differently, and other types go to cv::resize itself. For the
// glare stage's halved frame (`fast`) and the acuity loss's reduced
// levels.
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::retina {

// out = in halved to ((cols + 1) / 2, (rows + 1) / 2) by area means. out
// must not be in.
void halve_frame(const cv::Mat& in, cv::Mat& out);

}  // namespace eyestream::retina
