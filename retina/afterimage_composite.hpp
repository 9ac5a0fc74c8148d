// Puts the afterimage terms onto the tone-mapped frame (Jacobs et al. 2015 eq. 12;
// docs/model.md).
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::retina {

// Converts linear RGB to LMS cone stimuli (cone_space.hpp), with
// non-finite and negative results set to 0: what the photoreceptors receive.
cv::Mat to_cone_stimulus(const cv::Mat& rgb, int depth);

// out = LMS->RGB((1 + gain_excess) * RGB->LMS(tone_mapped)) + H * bleach,
// per pixel, all CV_32FC3 (gain_excess and bleach in LMS). The two maps
// are frame-sized, or smaller (one size) and read bilinearly as cv::resize
// INTER_LINEAR would enlarge them.
// Where both are exactly 0 (a retina at rest) the pixel is copied
// unchanged, so a steady scene shows the plain tone curve bit for bit.
void composite_afterimages(const cv::Mat& tone_mapped, const cv::Mat& gain_excess, const cv::Mat& bleach, cv::Mat& out);

}  // namespace eyestream::retina
