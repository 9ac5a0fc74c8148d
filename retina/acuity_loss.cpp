#include "retina/acuity_loss.hpp"

#include "retina/acuity_curve.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace eyestream::retina {

AcuityLoss::AcuityLoss(const AcuityParams& p, double pixels_per_degree, std::uint64_t seed, double bottom_log,
                       double top_log)
    : params_(p), seed_(seed) {
  // Bands needing more than the eye's limit at 10^0.75 = 5.6 cd/m^2 (42
  // c/deg; the limit rises only to 44 c/deg at 10 cd/m^2, under one octave
  // step) share the threshold of that level.
  const double finest_cpd = acuity_limit_cpd(0.75);
  for (int i = 0; i < p.bands; ++i) {
    const double sigma_deg = p.sigma0_arcmin * std::pow(2.0, i) / 60.0;
    sigmas_px_.push_back(sigma_deg * pixels_per_degree);
    const double needed = std::min(p.band_margin * gaussian_cutoff_cpd(sigma_deg), finest_cpd);
    tau_.push_back((acuity_log_luminance(needed) - bottom_log) / (top_log - bottom_log));
  }
  noise_.cell_px = std::max(1.0, p.noise_cell_deg * pixels_per_degree);
  noise_.period_s = p.noise_period_s;
  noise_.clip = p.noise_clip;
}

namespace {

// The noise's share at rho: whole through the mesopic range, fading to
// nothing across the first decade of photopic light (rho 1 to 1.5).
double noise_share(double rho) { return std::clamp((1.5 - rho) / 0.5, 0.0, 1.0); }

}  // namespace

double AcuityLoss::rho_all_kept() const {
  // The lowest rho whose lowest possible level, rho - g clip share(rho),
  // clears every threshold (the level rises with rho).
  const double tau = *std::max_element(tau_.begin(), tau_.end());
  const auto lowest = [&](double rho) { return rho - params_.noise_gain * params_.noise_clip * noise_share(rho); };
  double lo = tau, hi = tau + params_.noise_gain * params_.noise_clip;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (lowest(mid) > tau ? hi : lo) = mid;
  }
  return hi;
}

cv::Mat AcuityLoss::level(const cv::Mat& rho, double t_s, double gaze_x, double gaze_y) const {
  cv::Mat x = smooth_noise(rho.size(), t_s, noise_, seed_, RandomStream::kAcuity, {gaze_x, gaze_y});
  // Jacobs et al. 2015 eq. 15: rho + g X, the noise fading out above rho = 1.
  cv::Mat level(rho.size(), CV_32F);
  const float g = float(params_.noise_gain);
  for (int y = 0; y < rho.rows; ++y) {
    const float* r = rho.ptr<float>(y);
    const float* n = x.ptr<float>(y);
    float* o = level.ptr<float>(y);
    for (int i = 0; i < rho.cols; ++i) o[i] = r[i] + g * n[i] * float(noise_share(r[i]));
  }
  return level;
}

void acuity_blur(const cv::Mat& src, cv::Mat& dst, double sigma, double pyramid_from_px) {
  int f = 1;
  while (pyramid_from_px > 0 && sigma >= pyramid_from_px && sigma / (2 * f) >= 3.0 && src.cols / (2 * f) >= 8 &&
         src.rows / (2 * f) >= 8)
    f *= 2;
  if (f == 1) {
    cv::GaussianBlur(src, dst, cv::Size(0, 0), sigma, sigma, cv::BORDER_REPLICATE);
    return;
  }
  cv::Mat small;
  cv::resize(src, small, cv::Size((src.cols + f - 1) / f, (src.rows + f - 1) / f), 0, 0, cv::INTER_AREA);
  // The box reduction and the bilinear enlargement blur by about f^2/12 and
  // f^2/6 px^2 of variance themselves: the reduced blur supplies the rest.
  const double s = std::sqrt(std::max(sigma * sigma - f * f / 4.0, 1.0)) / f;
  cv::GaussianBlur(small, small, cv::Size(0, 0), s, s, cv::BORDER_REPLICATE);
  cv::resize(small, dst, src.size(), 0, 0, cv::INTER_LINEAR);
}

void AcuityLoss::apply(cv::Mat& image, const cv::Mat& level) const {
  CV_Assert(image.type() == CV_32FC3 && level.type() == CV_32F && level.size() == image.size());
  // Blur levels L_i (sigma_i), each from the previous with the missing
  // variance; band i = L_(i-1) - L_i. Sum of kept bands plus the residual:
  // out = L_n + sum_i [level > tau_i] (L_(i-1) - L_i)  (Jacobs et al. 2015 eq. 14).
  std::vector<cv::Mat> blurred(size_t(params_.bands) + 1);
  blurred[0] = image.clone();
  double previous = 0.0;
  for (int i = 0; i < params_.bands; ++i) {
    const double extra = std::sqrt(std::max(sigmas_px_[size_t(i)] * sigmas_px_[size_t(i)] - previous * previous, 0.0));
    previous = sigmas_px_[size_t(i)];
    if (extra < 0.05)
      blurred[size_t(i) + 1] = blurred[size_t(i)];
    else
      acuity_blur(blurred[size_t(i)], blurred[size_t(i) + 1], extra, params_.pyramid_from_px);
  }
  const int bands = params_.bands;
  std::vector<float> tau(tau_.begin(), tau_.end());
  cv::parallel_for_(cv::Range(0, image.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const float* lv = level.ptr<float>(y);
      cv::Vec3f* out = image.ptr<cv::Vec3f>(y);
      for (int x = 0; x < image.cols; ++x) {
        cv::Vec3f sum = blurred[size_t(bands)].ptr<cv::Vec3f>(y)[x];
        for (int i = 0; i < bands; ++i) {
          if (lv[x] > tau[i]) sum += blurred[size_t(i)].ptr<cv::Vec3f>(y)[x] - blurred[size_t(i) + 1].ptr<cv::Vec3f>(y)[x];
        }
        out[x] = sum;
      }
    }
  });
}

}  // namespace eyestream::retina
