// Conversion between RGB primaries, for frames tagged with other primaries
// than Rec.709 (OpenEXR `chromaticities`, BT.2020 video).
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::io {

// CIE 1931 xy chromaticities of an RGB space's primaries and white.
struct Chromaticities {
  double rx, ry, gx, gy, bx, by, wx, wy;
};

Chromaticities rec709_chromaticities();
Chromaticities bt2020_chromaticities();

// True when the values are finite, every y is positive and the primaries
// span a triangle (a singular set would give a singular matrix).
bool valid_chromaticities(const Chromaticities& c);

// 3x3 matrix taking linear RGB in `from` to linear Rec.709 (column vectors:
// out = M * in). White of `from` is carried to D65 by the Bradford
// transform, so `from`'s white (1,1,1) maps to Rec.709 white (1,1,1).
// Luminance is preserved: Y(out) equals Y(in) of the source space.
cv::Matx33d to_rec709_matrix(const Chromaticities& from);

// True when `m` is the identity within 1e-6 (conversion can be skipped).
bool is_identity(const cv::Matx33d& m);

// Applies `m` to every pixel of a CV_32FC3 image in place. Out-of-gamut
// results stay negative (never clipped here).
void apply_matrix(cv::Mat& rgb, const cv::Matx33d& m);

}  // namespace eyestream::io
