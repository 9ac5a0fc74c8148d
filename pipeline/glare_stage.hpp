// The eye's optics: turns the scene into the retinal image the retina sees
// (seeds 000, 003; MODEL.md 1). Bright veils then also adapt and bleach.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <optional>

#include "glare/fft_convolver.hpp"
#include "glare/split_convolver.hpp"
#include "glare/psf_kernel.hpp"
#include "pipeline/plan.hpp"

namespace eyestream::pipeline {

class GlareStage {
 public:
  // Builds the component kernels and their spectra once for the sequence.
  explicit GlareStage(const Plan& plan);

  // The retinal image of `rgb` (finite, cd/m^2) for a viewer adapted to
  // 10^adaptation_log. Mode "excess" spreads only the light above the
  // display peak, colour kept (seeds 000 and 003), and adds it back; "full"
  // spreads everything. When nothing exceeds the display peak in excess
  // mode, returns `rgb` itself and sets *ran to false: no glare work
  // (unless the plan says not to skip).
  cv::Mat apply(const cv::Mat& rgb, double adaptation_log, bool* ran = nullptr) const;

  // The veiling luminance (cd/m^2) at (x, y) from the light more than
  // exclusion_deg away (glare/veiling_luminance.hpp), for the viewer at
  // this adaptation; nothing with the Gaussian model (it is no eye PSF).
  std::optional<double> veil_at(const cv::Mat& luminance, double adaptation_log, double x, double y,
                                double exclusion_deg) const;

  // The PSF's component kernels (empty with the Gaussian model, and with
  // the split engine unless a report needs them).
  const glare::ComponentKernels& kernels() const { return kernels_; }

 private:
  // Convolves `rgb` with the frame's PSF.
  cv::Mat spread(const cv::Mat& rgb, double adaptation_log) const;

  const Plan plan_;
  const glare::EyeOptics optics_;
  glare::ComponentKernels kernels_;
  std::unique_ptr<glare::FftConvolver> convolver_;     // exact engine
  std::unique_ptr<glare::SplitConvolver> split_;       // or the split one
};

}  // namespace eyestream::pipeline
