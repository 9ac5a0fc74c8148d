// Disability-glare measures at a point of the visual field: the veiling
// luminance from the eye's PSF, and the threshold increment of road-
// lighting practice.
#pragma once

#include <opencv2/core.hpp>

#include "glare/psf_kernel.hpp"

namespace eyestream::glare {

// The luminance (cd/m^2) scattered onto the point (x, y) (frame pixels,
// origin at the top-left corner) from every pixel of `luminance` (CV_32F,
// cd/m^2) more than exclusion_px away: sum over p of L(p) K(point - p),
// with K the kernel for weights `w` (green channel's halo). For a small
// source of illuminance E at the eye and angle t, this is E P(t), P the
// PSF per steradian (Spencer et al. 1995).
double veiling_luminance(const cv::Mat& luminance, const ComponentKernels& k, const PsfWeights& w, double x, double y,
                         double exclusion_px);

// The same between pixel centres: the veils at the four pixel centres
// around (x, y), interpolated bilinearly, in one sweep over the sources.
double veiling_luminance_between(const cv::Mat& luminance, const ComponentKernels& k, const PsfWeights& w, double x,
                                 double y, double exclusion_px);

// Threshold increment TI = 65 L_v / L_av^0.8 (%), L_av the adaptation
// luminance (road-lighting practice; valid for L_av from about 0.05 to
// 5 cd/m^2, see threshold_increment_valid).
double threshold_increment(double veil_cd_m2, double adaptation_cd_m2);
bool threshold_increment_valid(double adaptation_cd_m2);

}  // namespace eyestream::glare
