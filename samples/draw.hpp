// Drawing helpers for scenes in physical units. Every light is drawn by
// energy: a disc of luminance L and radius r adds L * pi r^2 (cd/m^2 times
// pixel area) to the frame whatever its size, so a distant light fades
// into a sub-pixel point with the right intensity.
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::samples {

// Adds a disc of luminance `rgb` (cd/m^2 per channel) centred at (x, y)
// pixels with radius r pixels. Discs below one pixel deposit their energy
// bilinearly at the centre; larger ones are supersampled 8x8 per pixel.
void add_disc(cv::Mat& frame, double x, double y, double radius_px, const cv::Vec3f& rgb);

// Paints an opaque rectangle [x0, x1) x [y0, y1) (pixels, fractional) of
// luminance `rgb` over the frame, each pixel blended by the fraction of it
// covered. Returns the mask (CV_8U, 255) of the pixels at least half
// covered.
cv::Mat paint_rect(cv::Mat& frame, double x0, double y0, double x1, double y1, const cv::Vec3f& rgb);

// A colour of luminance `luminance` (cd/m^2) with chromaticity given by
// the linear Rec.709 ratio `tint` (any scale).
cv::Vec3f with_luminance(const cv::Vec3f& tint, float luminance);

}  // namespace eyestream::samples
