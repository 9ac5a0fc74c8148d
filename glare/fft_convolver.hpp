// Exact glare convolution by FFT (FFTW, double precision), zero-padded so
// nothing wraps around (MODEL.md 1.3). The spectra of the component
// kernels are computed once; each frame combines them with its weights.
#pragma once

#include <complex>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "glare/psf_kernel.hpp"

namespace eyestream::glare {

class FftConvolver {
 public:
  // For frames of the size the kernels were built for.
  explicit FftConvolver(const ComponentKernels& kernels);
  ~FftConvolver();
  FftConvolver(const FftConvolver&) = delete;
  FftConvolver& operator=(const FftConvolver&) = delete;

  // Convolves each channel of `rgb` (CV_32FC3, finite) with that channel's
  // combined kernel for `w`; light that leaves the frame is lost, none is
  // added. Negative rounding residue is set to 0. The three channels run in
  // parallel with plans fixed at construction (FFTW_ESTIMATE), so results
  // do not depend on the thread count or on timing.
  cv::Mat convolve(const cv::Mat& rgb, const PsfWeights& w) const;

 private:
  struct Channel;
  int width_, height_, nx_, ny_;
  std::vector<std::complex<double>> core_, inner_, outer_, halo_[3];
  std::vector<std::unique_ptr<Channel>> channels_;
};

// The smallest n >= minimum whose prime factors are 2, 3, 5 and 7 (fast FFT sizes).
int fft_size(int minimum);

}  // namespace eyestream::glare
