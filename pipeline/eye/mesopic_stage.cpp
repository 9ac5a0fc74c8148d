#include "pipeline/eye/mesopic_stage.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "retina/luminance.hpp"
#include "retina/mesopic.hpp"
#include "retina/tone_map.hpp"

namespace eyestream::pipeline {

MesopicStage::MesopicStage(const Plan& plan) : plan_(plan) {
  if (plan.mesopic.acuity)
    acuity_ =
        std::make_unique<retina::AcuityLoss>(plan.mesopic.acuity_params, plan.pixels_per_degree, plan.encoding.seed,
                                             plan.mesopic.colour.bottom_log, plan.mesopic.colour.top_log);
}

cv::Mat MesopicStage::acuity_level(const cv::Mat& rgb, double adaptation_log, double time_s, double gaze_x,
                                   double gaze_y) const {
  // At the frame's size, read from the reduced map as render() reads it.
  const cv::Mat reduced =
      level_of(retina::floored_luminance(rgb, plan_.dark_cd_m2), adaptation_log, time_s, gaze_x, gaze_y);
  return retina::enlarged_level(reduced, rgb.size());
}

cv::Mat MesopicStage::level_of(const cv::Mat& floored, double adaptation_log, double time_s, double gaze_x,
                               double gaze_y) const {
  // log10 of the local luminance, low-passed at the coarsest band, held
  // reduced by the level map's factor (1 at reference).
  const int f = acuity_->level_factor(floored.size());
  const cv::Mat luminance = retina::acuity_lowpass(floored, acuity_->sigmas_px().back(), f);
  const retina::MesopicParams& m = plan_.mesopic.colour;
  const float floor_rho = float(retina::mesopic_rho(adaptation_log, m));
  cv::Mat rho(luminance.size(), CV_32F);
  cv::parallel_for_(cv::Range(0, rho.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const float* l = luminance.ptr<float>(y);
      float* r = rho.ptr<float>(y);
      for (int x = 0; x < rho.cols; ++x) r[x] = std::max(float(retina::mesopic_rho(std::log10(l[x]), m)), floor_rho);
    }
  });
  return acuity_->level(rho, time_s, gaze_x, gaze_y, f);
}

void MesopicStage::render(cv::Mat rgb, const retina::ToneCurve& curve, double adaptation_log, double time_s,
                          cv::Mat& out, StageActivity* activity, double gaze_x, double gaze_y,
                          const cv::Mat& given_floored) const {
  retina::MesopicColour colour;
  const bool tinted = plan_.mesopic.enabled && retina::mesopic_colour(adaptation_log, plan_.mesopic.colour, colour);
  const bool local = tinted && plan_.mesopic.colour.local_sigma_deg > 0.0;
  // Above rho_all_kept no band can be lost: the loss is skipped, exactly
  // (its result would equal its input), unless the plan forbids skipping.
  const bool blur = plan_.mesopic.enabled && acuity_ &&
                    (!plan_.skip || retina::mesopic_rho(adaptation_log, plan_.mesopic.colour) < acuity_->rho_all_kept());
  // The frame's floored luminance, once for both effects that read it.
  const cv::Mat floored = !(local || blur)        ? cv::Mat()
                          : !given_floored.empty() ? given_floored
                                                   : retina::floored_luminance(rgb, plan_.dark_cd_m2);
  cv::Mat rho;
  if (local) {
    const double sigma = plan_.mesopic.colour.local_sigma_deg * plan_.pixels_per_degree;
    // Held reduced as the acuity's levels are (pyramid_from_px: at 1080p's
    // 64 px/deg a quarter each way in `balanced`, an eighth in `fast`):
    // the luminance low-passed on a grid reduced by f, rho there, read back
    // bilinearly.
    const double from_px = plan_.mesopic.acuity_params.pyramid_from_px;
    int f = 1;
    while (from_px > 0.0 && sigma / (2 * f) >= from_px / 2 && floored.cols / (2 * f) >= 8 && floored.rows / (2 * f) >= 8)
      f *= 2;
    if (f == 1) {
      retina::local_rho(floored, adaptation_log, sigma, plan_.mesopic.colour, rho);
    } else {
      cv::Mat reduced;
      retina::local_rho(retina::acuity_lowpass(floored, sigma, f), adaptation_log, 0.0, plan_.mesopic.colour, reduced);
      cv::resize(reduced, rho, floored.size(), 0, 0, cv::INTER_LINEAR);
    }
    colour.rho_map = &rho;
  }
  if (tinted)
    retina::tone_map(rgb, curve, colour, out);
  else
    retina::tone_map(rgb, curve, out);
  rgb.release();
  if (blur) acuity_->apply(out, level_of(floored, adaptation_log, time_s, gaze_x, gaze_y));
  if (activity) {
    activity->mesopic = tinted;
    activity->acuity = blur;
  }
}

}  // namespace eyestream::pipeline
