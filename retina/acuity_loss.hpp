// Stochastic loss of spatial acuity in low light (seed 001 sec. 2.3.3, eqs.
// 14-15; MODEL.md 3).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "retina/smooth_noise.hpp"

namespace eyestream::retina {

struct AcuityParams {
  // Band edges sigma_i = sigma0 * 2^i, i = 0..7, in arcminutes. Seed 001
  // App. A's extracted "0.75 x 2 i/4" is read as 0.75 * 2^i / 4 pixels of
  // the seed's 64 px/deg display (0.92 arcmin per pixel), octave-spaced like
  // the Laplacian pyramids the seed cites: 0.17 to 22 arcmin, so that deep
  // mesopic vision is "a severely blurred representation" (sec. 2.3.3).
  // The reading 0.75 * 2^(i/4) would end at 2.5 arcmin, under a pixel on
  // most displays: no visible loss at all.
  double sigma0_arcmin = 0.172;
  int bands = 8;
  double noise_gain = 0.25;      // g (seed 001 App. A)
  double noise_cell_deg = 0.5;   // spatial spacing of the coarse noise grid
  double noise_period_s = 0.25;  // temporal spacing of the coarse noise grid
  double noise_clip = 2.0;       // X is clipped to [-2, 2]
  // Blurs wider than this many pixels run on the image reduced by a power
  // of two (at least 3 px of blur left there) and are enlarged back: the
  // coarse bands are smooth, so little is lost (quality presets); 0: every
  // blur at full resolution (reference).
  double pyramid_from_px = 0.0;
};

// Splits an image into difference-of-Gaussian bands G_i between sigma_(i-1)
// and sigma_i (sigma_(-1) = 0) plus the low-pass residual, and keeps band i
// where rho + g X > tau_i (seed 001 eq. 15). The thresholds tau_i =
// (bands - i - 0.5) / bands spread over the mesopic range with the finest
// band highest, so the finest detail goes first as light falls. (Seed 001
// App. A lists rho_i = 0.286 i, 0 to 2: read literally it would drop coarse
// bands first and blur scenes at 100 cd/m^2; eyestream keeps its count and
// even spacing over rho in [0, 1].) With X clipped to +-2, every band is
// kept once rho >= tau_0 + 2 g, so photopic scenes are untouched exactly.
// Gaussian blur of `src` by sigma px (replicated border); a blur of at
// least pyramid_from_px (> 0) runs on a copy reduced by a power of two.
void acuity_blur(const cv::Mat& src, cv::Mat& dst, double sigma, double pyramid_from_px);

class AcuityLoss {
 public:
  AcuityLoss(const AcuityParams& params, double pixels_per_degree, std::uint64_t seed);

  // The lowest rho at which every band is always kept.
  double rho_all_kept() const;
  // Band edges in pixels.
  const std::vector<double>& sigmas_px() const { return sigmas_px_; }

  // rho + g X at each pixel (CV_32F) for a rho map (CV_32F) at time t_s.
  cv::Mat level(const cv::Mat& rho, double t_s) const;

  // Applies the loss to `image` (CV_32FC3) in place for a level map from level().
  void apply(cv::Mat& image, const cv::Mat& level) const;

 private:
  AcuityParams params_;
  std::vector<double> sigmas_px_;
  SmoothNoiseParams noise_;
  std::uint64_t seed_;
};

}  // namespace eyestream::retina
