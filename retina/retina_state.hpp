// Per-site, per-cone photopigment bleaching B and calcium deficit D on the
// retinal grid, and the afterimage maps they produce (Jacobs et al. 2015 sec. 2.2;
// docs/model.md).
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "retina/photoreceptor.hpp"
#include "retina/tone_curve.hpp"

namespace eyestream::retina {

struct AfterimageOptions {
  bool bleaching = true;         // bleaching afterimages (the j1 term)
  bool local_adaptation = true;  // adaptation afterimages (the alpha^j2 gain)
};

// The two afterimage terms on the grid (both CV_32FC3, LMS), faded with
// eccentricity, each 0 at rest: `gain_excess` = alpha^j2 - 1 per cone and
// `bleach` = j1 (C/C_max) max(B - B_inf, 0) per cone. Zero at rest stays
// exactly zero through bilinear drawing to the display.
struct AfterimageMaps {
  cv::Mat gain_excess;
  cv::Mat bleach;
  float largest = 0.0f;  // the largest |value| in either map
};

// A stimulus's equilibrium bleaching B_inf and response R per site and cone.
struct RestOfStimulus {
  cv::Mat bleached, response;
};

class RetinaState {
 public:
  // `double_precision` keeps the state in CV_64F (reference mode).
  RetinaState(cv::Size grid, const PhotoreceptorParams& params, bool double_precision);

  // Sets every site to its equilibrium for the stimulus `lms` (grid-sized,
  // cone stimuli >= 0 in cd/m^2-equivalents): the viewer starts at rest.
  void rest(const cv::Mat& lms, const ToneCurve& curve);

  // Advances every site by dt_s seconds at the constant stimulus `lms`,
  // exactly (Jacobs et al. 2015 eqs. 5 and 9; in float with e^x to 1.5e-7,
  // cone_step_row.hpp). Non-finite or negative stimuli count as
  // 0. Afterwards 0 <= B <= 1 and 0 <= D <= C_max. Remembers the stimulus's
  // equilibrium and responses for soften() and afterimages().
  void step(const cv::Mat& lms, const ToneCurve& curve, double dt_s);

  // Spreads the departure from equilibrium for the last stimulus (B - B_inf
  // and D - D_inf) by a blur that adds exactly `variance_sites2` (sites^2)
  // to its spatial variance along each axis: afterimages look soft (Jacobs
  // et al. 2015 sec. 2.4) while a retina at rest stays exactly at rest.
  // Variances add, so many small steps blur as much as one large one
  // whatever the frame rate or grid (diffusion.hpp). Needs B_inf and R
  // (holds_rest()).
  void soften(double variance_sites2);

  // The afterimage terms for the last stimulus, weighted by `visibility`
  // (CV_32F, grid-sized, in [0, 1]: the fall-off away from the fovea).
  // With a region (inside the grid, not empty), only its sites are
  // computed and the maps are its size (site (x, y) of the grid at
  // (x - region.x, y - region.y)): the frame sees about a quarter of the grid.
  AfterimageMaps afterimages(const AfterimageOptions& options, const cv::Mat& visibility,
                             std::optional<cv::Rect> region = std::nullopt) const;
  // afterimages(options, visibility).largest, without making the maps (two
  // grid-sized images).
  float largest_afterimage(const AfterimageOptions& options, const cv::Mat& visibility) const;

  const cv::Mat& bleached() const { return bleached_; }  // B, LMS
  const cv::Mat& deficit() const { return deficit_; }    // D = C_max - C, LMS
  double calcium_max() const { return c_max_; }
  cv::Mat calcium() const;  // C = C_max - D, LMS

  // B_inf and R of the last stimulus are held from step() (or rest())
  // until release_rest(); soften() and the afterimages need them.
  // recall_rest() makes them again from that stimulus and tone curve, the
  // same bytes step() made; rest_for() returns them for any stimulus.
  bool holds_rest() const { return !response_.empty(); }
  void release_rest();
  void recall_rest(const cv::Mat& lms, const ToneCurve& curve);
  RestOfStimulus rest_for(const cv::Mat& lms, const ToneCurve& curve) const;

  // The whole state for checkpoints: B, D, B_inf and R (the last two empty
  // before the first step or after release_rest()), and back. restore()
  // takes what save() gave.
  std::vector<cv::Mat> save() const { return {bleached_, deficit_, bleached_rest_, response_}; }
  void restore(const std::vector<cv::Mat>& mats);

 private:
  AfterimageMaps afterimage_terms(const AfterimageOptions& options, const cv::Mat& visibility,
                                  std::optional<cv::Rect> within, bool with_maps) const;

  PhotoreceptorParams params_;
  double c_max_;
  cv::Mat bleached_, deficit_;
  cv::Mat bleached_rest_, response_;  // B_inf and R of the last stimulus
};

}  // namespace eyestream::retina
