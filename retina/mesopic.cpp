#include "retina/mesopic.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "retina/gaussian_blur.hpp"
#include "retina/luminance.hpp"

namespace eyestream::retina {

double mesopic_rho(double log_l, const MesopicParams& p) {
  return (log_l - p.bottom_log) / (p.top_log - p.bottom_log);  // Jacobs et al. 2015 eq. 13
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

void local_rho(const cv::Mat& luminance, double adaptation_log, double sigma_px, const MesopicParams& p, cv::Mat& rho) {
  CV_Assert(luminance.type() == CV_32F);
  cv::Mat l = luminance;
  if (sigma_px > 0.0) {
    cv::Mat blurred;
    gaussian_blur(luminance, blurred, sigma_px);
    l = blurred;
  }
  rho.create(luminance.size(), CV_32F);
  const float a = float(adaptation_log), bottom = float(p.bottom_log), span = float(p.top_log - p.bottom_log);
  const float margin = float(p.local_margin_log);
  cv::parallel_for_(cv::Range(0, l.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const float* in = l.ptr<float>(y);
      float* o = rho.ptr<float>(y);
      for (int x = 0; x < l.cols; ++x) o[x] = std::clamp((std::max(a, std::log10(in[x]) - margin) - bottom) / span, 0.0f, 1.0f);
    }
  });
}

}  // namespace eyestream::retina
