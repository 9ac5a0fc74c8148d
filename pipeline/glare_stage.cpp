#include "pipeline/glare_stage.hpp"

#include <opencv2/imgproc.hpp>

#include "glare/veiling_luminance.hpp"
#include "retina/luminance.hpp"

namespace eyestream::pipeline {

GlareStage::GlareStage(const Plan& plan) : plan_(plan), optics_(plan.eye_optics()) {
  if (plan.glare.gaussian) return;  // no kernels: a separable blur does the work
  // The full kernels also give the report its veil (veiling_luminance.hpp).
  if (plan.glare.tail_factor <= 1 || plan.report)
    kernels_ = glare::build_component_kernels(plan.width, plan.height, plan.pixels_per_degree, optics_);
  if (plan.glare.tail_factor > 1)
    split_ = std::make_unique<glare::SplitConvolver>(plan.width, plan.height, plan.pixels_per_degree,
                                                     plan.glare.tail_factor, optics_);
  else
    convolver_ = std::make_unique<glare::FftConvolver>(kernels_);
}

std::optional<double> GlareStage::veil_at(const cv::Mat& luminance, double adaptation_log, double x, double y,
                                          double exclusion_deg) const {
  if (plan_.glare.gaussian || kernels_.core.empty()) return std::nullopt;
  return glare::veiling_luminance(luminance, kernels_, optics_.weights(adaptation_log), x, y,
                                  exclusion_deg * plan_.pixels_per_degree);
}

cv::Mat GlareStage::spread(const cv::Mat& rgb, double adaptation_log) const {
  if (plan_.glare.gaussian) {
    // seed 003: a Gaussian of sigma 0.34 deg; light leaving the frame is lost.
    const double sigma = plan_.glare.gaussian_sigma_deg * plan_.pixels_per_degree;
    cv::Mat out;
    cv::GaussianBlur(rgb, out, cv::Size(0, 0), sigma, sigma, cv::BORDER_CONSTANT);
    return out;
  }
  const glare::PsfWeights w = optics_.weights(adaptation_log);
  return split_ ? split_->convolve(rgb, w) : convolver_->convolve(rgb, w);
}

cv::Mat GlareStage::apply(const cv::Mat& rgb, double adaptation_log, bool* ran) const {
  if (plan_.glare.full) {
    if (ran) *ran = true;
    return spread(rgb, adaptation_log);
  }
  // The excess over the display peak, with the pixel's colour (seed 000 sec.
  // 3.2, seed 003): dL = max(L - L_dmax, 0), spread, added back.
  const float peak = float(plan_.glare.display_peak_cd_m2);
  cv::Mat excess(rgb.size(), CV_32FC3), kept(rgb.size(), CV_32FC3);
  std::vector<unsigned char> row_has(size_t(rgb.rows), 0);
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const cv::Vec3f* in = rgb.ptr<cv::Vec3f>(y);
      cv::Vec3f* e = excess.ptr<cv::Vec3f>(y);
      cv::Vec3f* k = kept.ptr<cv::Vec3f>(y);
      for (int x = 0; x < rgb.cols; ++x) {
        const float l = retina::photopic_luminance(in[x]);
        const float share = l > peak ? (l - peak) / l : 0.0f;
        e[x] = in[x] * share;
        k[x] = in[x] - e[x];
        row_has[size_t(y)] |= share > 0.0f;
      }
    }
  });
  const bool any = std::any_of(row_has.begin(), row_has.end(), [](unsigned char v) { return v != 0; });
  if (ran) *ran = any;
  if (!any && plan_.skip) return rgb;
  if (ran) *ran = true;
  return kept + spread(excess, adaptation_log);
}

}  // namespace eyestream::pipeline
