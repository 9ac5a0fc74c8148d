#include "retina/mesopic.hpp"

#include <algorithm>

#include "retina/luminance.hpp"

namespace eyestream::retina {

double mesopic_rho(double log_l, const MesopicParams& p) {
  return (log_l - p.bottom_log) / (p.top_log - p.bottom_log);  // seed 001 eq. 13
}

bool mesopic_colour(double adaptation_log, const MesopicParams& p, MesopicColour& out) {
  const double rho = mesopic_rho(adaptation_log, p);
  if (rho >= 1.0 || !(p.purkinje || p.hue_shift)) return false;
  out.rho = float(std::clamp(rho, 0.0, 1.0));
  out.scotopic_weights =
      p.purkinje ? cv::Vec3f(float(p.scotopic_weights[0]), float(p.scotopic_weights[1]), float(p.scotopic_weights[2]))
                 : cv::Vec3f(kPhotopicR, kPhotopicG, kPhotopicB);
  const cv::Vec3f tint(float(p.scotopic_tint[0]), float(p.scotopic_tint[1]), float(p.scotopic_tint[2]));
  out.tint_ratio = tint / photopic_luminance(tint);
  out.hue_shift = p.hue_shift;
  return true;
}

}  // namespace eyestream::retina
