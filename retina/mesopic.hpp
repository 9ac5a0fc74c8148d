// Mesopic colour: the Purkinje shift and the hue shift toward a dull purple
// (seed 001 sec. 2.3, eq. 13 and App. A; MODEL.md 3).
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::retina {

struct MesopicParams {
  double top_log = 0.0;      // m1: log10 cd/m^2 where vision is fully photopic
  double bottom_log = -2.0;  // m2: log10 cd/m^2 where it is fully scotopic
  // Scotopic RGB luminance weights wS (seed 001 App. A, after Kirk and O'Brien).
  double scotopic_weights[3] = {0.0, 0.8451, 0.1459};
  // The colour a neutral grey drifts to in the dark (Shin et al. via seed
  // 001 sec. 2.3.2: "a dull purple"), linear Rec.709, any scale: a purple
  // of hue about 285 deg and low saturation.
  double scotopic_tint[3] = {1.15, 0.90, 1.25};
  bool purkinje = true;   // mesopic luminance for the tone curve
  bool hue_shift = true;  // colour drifts toward the tint
};

// rho = (L - m2) / (m1 - m2) for log10 luminance L (seed 001 eq. 13),
// unclamped.
double mesopic_rho(double log_luminance, const MesopicParams& p);

// The per-frame colour model handed to the tone map when rho < 1.
struct MesopicColour {
  float rho = 1.0f;            // clamped to [0, 1]
  cv::Vec3f scotopic_weights;  // wS, or wP when the Purkinje shift is off
  cv::Vec3f tint_ratio;        // tint / its photopic luminance
  bool hue_shift = true;
};

// The colour model for adaptation level `adaptation_log`; nothing (plain
// photopic tone mapping) when rho >= 1 or both effects are off.
bool mesopic_colour(double adaptation_log, const MesopicParams& p, MesopicColour& out);

}  // namespace eyestream::retina
