// Glare convolution by FFT (FFTW, double precision), zero-padded so nothing
// wraps around (docs/model.md). The spectra of the component kernels are
// computed once (real: the PSF is point-symmetric, and a kernel that is
// not is refused); each frame combines them with its weights.
//
// Double, not single precision: FFT rounding spreads over the whole frame
// in proportion to its brightest light, and in single precision a 1e5
// cd/m^2 headlight left a 0.01 cd/m^2 road 20 % wrong far outside the
// kernel (tests/fft_convolver_test.cpp); in double it is 1e-9 of that, for
// about 15 % more time.
#pragma once

#include <memory>
#include <opencv2/core.hpp>

#include "glare/psf_kernel.hpp"
#include "glare/psf_weights.hpp"

namespace eyestream::glare {

class FftConvolver {
 public:
  // For frames of the size the kernels were built for ((2W - 1) wide).
  explicit FftConvolver(const ComponentKernels& kernels);
  // For width x height frames and centred kernels of any odd size: the
  // padding covers the kernels' reach, not the frame's.
  FftConvolver(const ComponentKernels& kernels, int width, int height);
  ~FftConvolver();
  FftConvolver(const FftConvolver&) = delete;
  FftConvolver& operator=(const FftConvolver&) = delete;

  // Convolves each channel of `rgb` (CV_32FC3, finite) with that channel's
  // combined kernel for `w` into `out` (CV_32FC3, reallocated only if its
  // size differs); light that leaves the frame is lost, none is added.
  // Negative rounding residue is set to 0. Rows and columns are
  // transformed in fixed blocks by fixed plans (estimated, or the shipped
  // wisdom's: fftw_planner.hpp), shared out among threads, so results do
  // not depend on the thread count or timing.
  void convolve(const cv::Mat& rgb, const PsfWeights& w, cv::Mat& out) const {
    convolve(rgb, same_in_every_channel(w), out);
  }
  cv::Mat convolve(const cv::Mat& rgb, const PsfWeights& w) const {
    cv::Mat out;
    convolve(rgb, w, out);
    return out;
  }
  // The same with each channel's own weights.
  void convolve(const cv::Mat& rgb, const ChannelWeights& w, cv::Mat& out) const;
  cv::Mat convolve(const cv::Mat& rgb, const ChannelWeights& w) const {
    cv::Mat out;
    convolve(rgb, w, out);
    return out;
  }

  // The padded transform size.
  cv::Size transform_size() const;
  // The channels whose spectra are held and transformed together: 3 where
  // their spectra take at most 16 MiB, else 1 (one after the other).
  int channels_at_once() const;

  struct Engine;

 private:
  std::unique_ptr<Engine> engine_;
};

// The smallest n >= minimum whose prime factors are 2, 3, 5 and 7, and from
// 64 up a multiple of 16 as well (fast FFT sizes for estimated plans).
int fft_size(int minimum);

}  // namespace eyestream::glare
