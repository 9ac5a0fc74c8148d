// A blur that adds an exact spatial variance, however small: the discrete
// diffusion step. A Gaussian sampled on a grid has far less variance than
// sigma^2 when sigma is below about one site (at sigma 0.13 sites it is
// nearly the identity), so per-frame blurs that should add up do not. The
// three-tap kernel [v/2, 1 - v, v/2] adds exactly v (sites^2) along its
// axis, and variances add under convolution, so n passes of v / n add v for
// any split of the time into frames.
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::retina {

// Adds `variance_sites2` to the spatial variance of `m` along each axis
// (replicated borders). Up to 4 sites^2 by passes of the three-tap kernel
// (each at most 0.5); beyond, by a Gaussian of sigma = sqrt(variance), whose
// sampled variance is within 0.1 % of sigma^2 there. A variance beyond the
// grid's squared diagonal is taken as that (the blur is uniform by then).
void diffuse(cv::Mat& m, double variance_sites2);

// state = clamp(rest_scale rest + diffuse(state - rest_scale rest), 0, hi),
// the departure from rest spread by `variance_sites2` as diffuse() does,
// in two fused sweeps per three-tap pass (no temporary departure image);
// CV_32FC3 or CV_64FC3. Beyond 4 sites^2, by diffuse() itself.
void diffuse_departure(cv::Mat& state, const cv::Mat& rest, double rest_scale, double variance_sites2, double hi);

}  // namespace eyestream::retina
