// Stochastic loss of spatial acuity in low light (Jacobs et al. 2015 sec. 2.3.3, eqs.
// 14-15).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "retina/smooth_noise.hpp"

namespace eyestream::retina {

struct AcuityParams {
  // Band edges sigma_i = sigma0 * 2^i, i = 0..7, in arcminutes. Jacobs et al. 2015
  // App. A's extracted "0.75 x 2 i/4" is read as 0.75 * 2^i / 4 pixels of
  // the seed's 64 px/deg display (0.92 arcmin per pixel), octave-spaced like
  // the Laplacian pyramids the seed cites: 0.17 to 22 arcmin, so that deep
  // mesopic vision is "a severely blurred representation" (sec. 2.3.3).
  // The reading 0.75 * 2^(i/4) would end at 2.5 arcmin, under a pixel on
  // most displays: no visible loss at all.
  double sigma0_arcmin = 0.172;
  int bands = 8;
  double noise_gain = 0.25;      // g (Jacobs et al. 2015 App. A)
  double noise_cell_deg = 0.5;   // spatial spacing of the coarse noise grid
  double noise_period_s = 0.25;  // temporal spacing of the coarse noise grid
  double noise_clip = 2.0;       // X is clipped to [-2, 2]
  // Band i is kept where the eye resolves this many times its 10 % cutoff
  // (acuity_loss.cpp; tuned with the stochastic thresholds, which keep finer
  // bands in places).
  double band_margin = 1.8;
  // Blur levels this many pixels wide or wider are held reduced by a power
  // of two (at least half this many pixels of blur left there) and read
  // bilinearly: the coarse bands are smooth, so little is lost (quality
  // presets); 0: every level at full resolution (reference).
  double pyramid_from_px = 0.0;
};

// Splits an image into difference-of-Gaussian bands G_i between sigma_(i-1)
// and sigma_i (sigma_(-1) = 0) plus the low-pass residual, and keeps band i
// where rho + g X > tau_i (Jacobs et al. 2015 eq. 15). The thresholds are
// calibrated to human acuity (acuity_curve.hpp): losing bands 0..k-1 leaves
// a Gaussian blur of sigma_(k-1), which passes gratings up to
// gaussian_cutoff_cpd(sigma_(k-1)) at 10 % contrast; band i is kept where
// the luminance L_i of rho = tau_i resolves band_margin times its cutoff.
// Octave bands make the resolution a staircase, and the stochastic
// thresholds keep finer bands in places; band_margin 1.8 centres the mean
// resolution on the human limit: within a factor 1.5 of it from 1e-3 to
// 10 cd/m^2 (tests/acuity_calibration_test.cpp). Bands needing more than
// the eye resolves at 5.6 cd/m^2 (42 c/deg) share the threshold of that
// level. The noise is the seed's through the mesopic range and fades out
// across the first photopic decade (rho 1 to 1.5: cone vision's acuity is
// not patchy), so with X clipped to +-2 every band is kept from rho 1.44
// (7.5 cd/m^2) up: photopic scenes are untouched exactly.
// Gaussian blur of `src` by sigma px (replicated border), held reduced by
// `factor` (a power of two: area reduction, then the rest of the blur, so
// that with a bilinear enlargement the variance is sigma^2).
cv::Mat acuity_lowpass(const cv::Mat& src, double sigma, int factor);

// A reduced level map (CV_32F) at a frame's size: bilinear, with
// cv::resize INTER_LINEAR's geometry, a row blended down then across
// (bilinear_rows.hpp), as AcuityLoss::apply() reads a reduced map.
cv::Mat enlarged_level(const cv::Mat& level, cv::Size frame);

class AcuityLoss {
 public:
  // rho of a log10 luminance L is (L - bottom_log) / (top_log - bottom_log)
  // (mesopic.hpp).
  AcuityLoss(const AcuityParams& params, double pixels_per_degree, std::uint64_t seed, double bottom_log = -2.0,
             double top_log = 0.0);

  // The lowest rho at which every band is always kept.
  double rho_all_kept() const;
  // Band edges in pixels.
  const std::vector<double>& sigmas_px() const { return sigmas_px_; }

  // The thresholds tau_i, finest band first.
  const std::vector<double>& thresholds() const { return tau_; }

  // The factor (a power of two) by which the level map of a frame is held
  // reduced: 1 at reference (pyramid_from_px 0), else the largest that
  // leaves the coarsest band 3 reduced pixels wide. The map is smooth at
  // that scale (the local luminance is low-passed there, the noise is
  // coarser still) and is read bilinearly.
  int level_factor(cv::Size frame) const;

  // rho + g X at each pixel (CV_32F) for a rho map (CV_32F) at time t_s,
  // with the gaze at (gaze_x, gaze_y) frame pixels: X lives on the retina,
  // so its pattern moves with the gaze (acuity is a property of the eye).
  // With factor > 1 the rho map is the frame reduced by it (pixel X of the
  // map is centred on frame position (X + 0.5) factor).
  cv::Mat level(const cv::Mat& rho, double t_s, double gaze_x = 0.0, double gaze_y = 0.0, int factor = 1) const;

  // Applies the loss to `image` (CV_32FC3) in place for a level map from
  // level(), at the image's size or held reduced (read at each pixel as
  // enlarged_level() reads it, without making the full-size map). Levels
  // beyond the coarsest a pixel takes, and those no pixel can take (bands
  // sharing a threshold) before a level of the same resolution, are not
  // made; each level made is the same blur of the image whichever others
  // the frame takes.
  void apply(cv::Mat& image, const cv::Mat& level) const;

 private:
  // Writes full-resolution blur level k to the pixels of `image` whose
  // first kept band is k.
  static void write_full_level(cv::Mat& image, const cv::Mat& first, const std::vector<std::uint8_t>& row_deepest,
                               int k, const cv::Mat& level);
  // The same for row y only.
  static void write_full_row(cv::Mat& image, const cv::Mat& first, const std::vector<std::uint8_t>& row_deepest, int k,
                             const cv::Mat& level, int y);

  AcuityParams params_;
  std::vector<double> sigmas_px_, tau_;
  SmoothNoiseParams noise_;
  std::uint64_t seed_;
};

}  // namespace eyestream::retina
