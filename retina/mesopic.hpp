// Mesopic colour: the Purkinje shift and the hue shift toward a dull purple
// (Jacobs et al. 2015 sec. 2.3, eq. 13 and App. A).
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::retina {

struct MesopicParams {
  double top_log = 0.0;      // m1: log10 cd/m^2 where vision is fully photopic
  double bottom_log = -2.0;  // m2: log10 cd/m^2 where it is fully scotopic
  // Scotopic RGB luminance weights wS (Jacobs et al. 2015 App. A, after Kirk and O'Brien).
  double scotopic_weights[3] = {0.0, 0.8451, 0.1459};
  // The colour a neutral grey drifts to in the dark (Shin et al. via seed
  // 001 sec. 2.3.2: "a dull purple"), linear Rec.709, any scale: a purple
  // of hue about 285 deg and low saturation.
  double scotopic_tint[3] = {1.15, 0.90, 1.25};
  bool purkinje = true;   // mesopic luminance for the tone curve
  bool hue_shift = true;  // colour drifts toward the tint
  // Local mesopic colour: rho at each place follows the brighter of the
  // adaptation level A and the local retinal luminance (low-passed by a
  // Gaussian of local_sigma_deg) less local_margin_log, so a bright light
  // keeps its colour at night (cones see it whatever the global adaptation)
  // while surfaces lit by the light the viewer is adapted to (reflectances
  // of 3-90 % about an 18 % grey lie within -0.8 and +0.7 log units of A)
  // drift to the scotopic purple exactly as with A alone. local_sigma_deg
  // 0: the adaptation level alone (Jacobs et al. 2015 as published).
  double local_sigma_deg = 0.1;
  double local_margin_log = 1.0;
};

// rho = (L - m2) / (m1 - m2) for log10 luminance L (Jacobs et al. 2015 eq. 13),
// unclamped.
double mesopic_rho(double log_luminance, const MesopicParams& p);

// The per-frame colour model handed to the tone map when rho < 1.
struct MesopicColour {
  float rho = 1.0f;            // clamped to [0, 1]
  const cv::Mat* rho_map = nullptr;  // or per pixel (CV_32F, in [0, 1]), when set
  cv::Vec3f scotopic_weights;  // wS, or wP when the Purkinje shift is off
  cv::Vec3f tint_ratio;        // tint / its photopic luminance
  bool hue_shift = true;
};

// The colour model for adaptation level `adaptation_log`; nothing (plain
// photopic tone mapping) when rho >= 1 or both effects are off.
bool mesopic_colour(double adaptation_log, const MesopicParams& p, MesopicColour& out);

// rho per pixel for local mesopic colour: clamp(rho(max(A, log10 L_local -
// margin)), 0, 1), L_local the frame's floored photopic luminance
// (floored_luminance(), CV_32F) blurred by sigma_px.
void local_rho(const cv::Mat& luminance, double adaptation_log, double sigma_px, const MesopicParams& p, cv::Mat& rho);

}  // namespace eyestream::retina
