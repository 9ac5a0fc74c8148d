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

// out(x, y) = sum over sources of in(x', y') k(x - x' + r, y - y' + r) for
// each channel's combined kernel, zero outside the frame (CV_64FC3).
cv::Mat direct_convolution(const cv::Mat& in, const glare::ComponentKernels& k, const glare::PsfWeights& w);

}  // namespace eyestream::test
