// The oracle for the glare FFT engines' tests: a direct sum over every
// kernel tap, computed here in double, and small random kernels to feed it.
#pragma once

#include <opencv2/core.hpp>

#include "glare/psf_kernel.hpp"
#include "glare/psf_weights.hpp"

namespace eyestream::test {

// Small random component kernels, (2r + 1) square, CV_64F, each summing to
// 1, point-symmetric as the eye's PSF is (k(-x, -y) = k(x, y)) unless
// `symmetric` is false.
glare::ComponentKernels random_kernels(int r, unsigned seed, bool symmetric = true);

// A 2r + 1 square kernel in the core slot that falls as 1 / (1 + d)^3 with
// the distance d (a PSF's shape), summing to 1; the other slots 0. With
// weights {core 1}: the headlight tests' kernel.
glare::ComponentKernels falloff_kernels(int r);
glare::PsfWeights core_only();

// The headlight tests' scene: a 0.01 cd/m^2 road, one 1e5 cd/m^2 headlight
// pixel at (160, 90). And the largest error of an engine's `out` for it
// (convolved with falloff_kernels(r), core_only()) beyond the headlight's
// square reach, in green, at every 7th row and column, against the direct
// sum of the road alone: only rounding can put the headlight there.
cv::Mat road_with_headlight(int width, int height);
double worst_road_error(const cv::Mat& out, int r);

// out(x, y) = sum over sources of in(x', y') k(x - x' + r, y - y' + r) for
// each channel's combined kernel, zero outside the frame (CV_64FC3).
cv::Mat direct_convolution(const cv::Mat& in, const glare::ComponentKernels& k, const glare::PsfWeights& w);

}  // namespace eyestream::test
