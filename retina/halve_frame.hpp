// An image halved each way by the mean of each 2 x 2 block: what
// cv::resize with INTER_AREA gives, bit for bit, made here row-parallel
// and vectorised for three-channel float images of even size (OpenCV's
// own runs on one thread there: 2.4 ms for a 1080p frame on this
// machine). Odd sizes, whose last row or column OpenCV weighs
// differently, and other types go to cv::resize itself. For the glare
// stage's halved frame (`fast`) and the acuity loss's reduced levels.
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::retina {

// out = in halved to ((cols + 1) / 2, (rows + 1) / 2) by area means. out
// must not be in.
void halve_frame(const cv::Mat& in, cv::Mat& out);

}  // namespace eyestream::retina
