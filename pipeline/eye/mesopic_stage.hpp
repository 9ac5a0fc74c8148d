// The scene as the viewer sees it at their adaptation level: tone curve with
// mesopic colour (Purkinje shift, hue shift) and stochastic acuity loss
// (Jacobs et al. 2015 sec. 2.3).
#pragma once

#include <memory>
#include <opencv2/core.hpp>

#include "pipeline/settings/plan.hpp"
#include "pipeline/eye/stage_activity.hpp"
#include "retina/acuity_loss.hpp"
#include "retina/tone_curve.hpp"

namespace eyestream::pipeline {

// Which luminance drives each effect: the colour effects follow the
// brighter of the adaptation level A (the state of the whole visual system,
// which changes smoothly with time) and the local retinal luminance
// low-passed at local_sigma_deg (cones see a bright light whatever the
// global adaptation), so a red tail light stays red at night while dim
// surfaces drift to the scotopic purple as before.
// Acuity follows the brighter of A and the local luminance low-passed at
// the coarsest band's scale: a dark-adapted viewer still resolves a lit
// sign, and a light-adapted one is never blurred.
class MesopicStage {
 public:
  explicit MesopicStage(const Plan& plan);

  // Tone-maps `rgb` (cd/m^2) with `curve` into `out`, adding the mesopic
  // effects the adaptation level calls for. At rho(A) >= 1 the colour is
  // the plain tone curve's; above the acuity stage's limit no band is lost:
  // photopic frames come out bit-identical to a run without this stage.
  // `activity` (may be null) receives which of the two effects ran.
  // The acuity noise lives on the retina: its pattern moves with the gaze
  // at (gaze_x, gaze_y).
  // `floored` (optional): rgb's luminance floored at the plan's dark
  // level, when the caller has it (retina::LuminanceField::luminance()).
  // `rgb` is let go of once tone-mapped: a caller that moves its only
  // reference in frees it for the acuity loss's levels.
  void render(cv::Mat rgb, const retina::ToneCurve& curve, double adaptation_log, double time_s, cv::Mat& out,
              StageActivity* activity = nullptr, double gaze_x = 0.0, double gaze_y = 0.0,
              const cv::Mat& floored = cv::Mat()) const;

  // rho + g X of the acuity loss for a frame (for reports and tests).
  cv::Mat acuity_level(const cv::Mat& rgb, double adaptation_log, double time_s, double gaze_x = 0.0,
                       double gaze_y = 0.0) const;

 private:
  // acuity_level() of the frame's floored luminance (floored_luminance()),
  // held reduced by the acuity's level_factor() (as AcuityLoss::apply()
  // takes it).
  cv::Mat level_of(const cv::Mat& floored, double adaptation_log, double time_s, double gaze_x, double gaze_y) const;

  const Plan plan_;
  std::unique_ptr<retina::AcuityLoss> acuity_;
};

}  // namespace eyestream::pipeline
