// The split glare engine: the PSF's sharp centre at full resolution, its
// smooth wide tail at reduced resolution (MODEL.md 1.3). With the window
// w(r) = 1 within R/2 pixels of the source, falling linearly to 0 at R:
//   K = K w            (near: full resolution, (2R+1)^2 pixels)
//     + K (1 - w)      (far: kernels integrated over factor x factor pixel
//                       footprints, on a frame reduced by that factor).
// The window is applied at pixel centres (near) and block centres (far),
// so near + far hold the undivided kernel's energy to within 0.05 %
// (tests/split_engine_test.cpp); the upsampled tail keeps its block
// energies, so the engine moves light without adding any. Near sources are scattered
// directly when the input is sparse (the excess over the display peak
// usually is), else by an FFT padded by R.
#pragma once

#include <memory>
#include <opencv2/core.hpp>

#include "glare/fft_convolver.hpp"
#include "glare/psf_kernel.hpp"

namespace eyestream::glare {

class SplitConvolver {
 public:
  // For width x height frames at pixels_per_degree; `factor` >= 2 is the
  // tail's reduction, R = 8 factor pixels.
  SplitConvolver(int width, int height, double pixels_per_degree, int factor, const EyeOptics& optics = EyeOptics());
  ~SplitConvolver();

  // As FftConvolver::convolve.
  cv::Mat convolve(const cv::Mat& rgb, const PsfWeights& w) const;

  int factor() const { return factor_; }
  int near_radius() const { return radius_; }

 private:
  cv::Mat spread_near(const cv::Mat& rgb, const PsfWeights& w) const;
  cv::Mat spread_far(const cv::Mat& rgb, const PsfWeights& w) const;

  int width_, height_, factor_, radius_, low_width_, low_height_;
  ComponentKernels near_;  // windowed, (2R+1) x (2R+1)
  std::unique_ptr<FftConvolver> far_;       // the tail
  std::unique_ptr<FftConvolver> near_fft_;  // the near part of a dense frame
};

}  // namespace eyestream::glare
