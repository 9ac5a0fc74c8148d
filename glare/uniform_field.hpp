// Whether a frame and what lies beyond it are one uniform field, within a
// relative tolerance: the PSF then returns the field itself (light scattered
// out of each pixel is replaced by as much scattered in), to within that
// tolerance, so the glare work can be skipped with that error bound.
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::glare {

// `rgb` linear Rec.709 in cd/m^2 (finite). True when every channel's
// largest value is at most (1 + tolerance) times its smallest and the
// (grey) surround lies within every channel's range widened by the same
// tolerance: a neutral field equal to its surround. A NaN pixel or
// surround is never uniform; `tolerance` is finite and >= 0.
bool is_uniform_field(const cv::Mat& rgb, double surround_cd_m2, double tolerance);

}  // namespace eyestream::glare
