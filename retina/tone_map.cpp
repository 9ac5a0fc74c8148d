#include "retina/tone_map.hpp"

#include <cmath>

#include "retina/luminance.hpp"

namespace eyestream::retina {

void tone_map(const cv::Mat& rgb, const ToneCurve& curve, cv::Mat& out) {
  // Photopic: rho = 1, photopic weights, nothing of the tint.
  MesopicColour photopic;
  photopic.rho = 1.0f;
  photopic.scotopic_weights = cv::Vec3f(kPhotopicR, kPhotopicG, kPhotopicB);
  photopic.tint_ratio = cv::Vec3f(0, 0, 0);
  photopic.hue_shift = false;
  tone_map(rgb, curve, photopic, out);
}

void tone_map(const cv::Mat& rgb, const ToneCurve& curve, const MesopicColour& m, cv::Mat& out) {
  CV_Assert(rgb.type() == CV_32FC3);
  out.create(rgb.size(), CV_32FC3);
  CV_Assert(!m.rho_map || (m.rho_map->size() == rgb.size() && m.rho_map->type() == CV_32F));
  const cv::Vec3f tint_ratio = m.hue_shift ? m.tint_ratio : cv::Vec3f(0, 0, 0);
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const cv::Vec3f* in = rgb.ptr<cv::Vec3f>(y);
      const float* rho_row = m.rho_map ? m.rho_map->ptr<float>(y) : nullptr;
      cv::Vec3f* o = out.ptr<cv::Vec3f>(y);
      for (int x = 0; x < rgb.cols; ++x) {
        const float rho = rho_row ? rho_row[x] : m.rho;
        const cv::Vec3f tint = tint_ratio * (1.0f - rho);
        const float scene_share = m.hue_shift ? rho : 1.0f;
        const cv::Vec3f p = in[x];
        const float yp = photopic_luminance(p);
        const float ys = m.scotopic_weights.dot(p);
        const float ym = rho * yp + (1.0f - rho) * ys;  // Purkinje: Jacobs et al. 2015 sec. 2.3.1
        if (!(yp > 0.0f) || !(ym > 0.0f) || !std::isfinite(ym)) {
          o[x] = cv::Vec3f(0, 0, 0);
          continue;
        }
        const float r = curve.response(ym);
        o[x] = p * (scene_share * r / yp) + tint * r;  // hue shift: Jacobs et al. 2015 sec. 2.3.2
      }
    }
  });
}

}  // namespace eyestream::retina
