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
    // apply() relies on it: a coarser band never needs more light.
    CV_Assert(i == 0 || tau_[size_t(i)] <= tau_[size_t(i) - 1]);
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

namespace {

// The value of `m` (CV_32FC3, the image reduced by f) at full-resolution
// pixel (x, y): bilinear, pixel centres at (x + 0.5) / f - 0.5, borders
// replicated (as cv::resize INTER_LINEAR).
cv::Vec3f sample(const cv::Mat& m, int f, int x, int y) {
  if (f == 1) return m.ptr<cv::Vec3f>(y)[x];
  const float inv = 1.0f / float(f);
  const float gx = std::clamp((float(x) + 0.5f) * inv - 0.5f, 0.0f, float(m.cols - 1));
  const float gy = std::clamp((float(y) + 0.5f) * inv - 0.5f, 0.0f, float(m.rows - 1));
  const int x0 = int(gx), y0 = int(gy);
  const int x1 = std::min(x0 + 1, m.cols - 1), y1 = std::min(y0 + 1, m.rows - 1);
  const float fx = gx - float(x0), fy = gy - float(y0);
  const cv::Vec3f* r0 = m.ptr<cv::Vec3f>(y0);
  const cv::Vec3f* r1 = m.ptr<cv::Vec3f>(y1);
  return (r0[x0] * (1.0f - fx) + r0[x1] * fx) * (1.0f - fy) + (r1[x0] * (1.0f - fx) + r1[x1] * fx) * fy;
}

}  // namespace

void AcuityLoss::apply(cv::Mat& image, const cv::Mat& level) const {
  CV_Assert(image.type() == CV_32FC3 && level.type() == CV_32F && level.size() == image.size());
  // Blur levels L_i of sigma_i (L_0 the image); band i = L_(i-1) - L_i is
  // kept where level > tau_i (Jacobs et al. 2015 eq. 14):
  //   out = L_n + sum_i [level > tau_i] (L_(i-1) - L_i).
  // The thresholds fall with i (coarser bands need less light), so the kept
  // bands are those from the first kept one, k, on, and the sum is L_k: each
  // pixel takes one level. A level of sigma_i >= pyramid_from_px is held
  // reduced by a power of two f (sigma_i / f >= pyramid_from_px / 2) and
  // read bilinearly; its blur counts what the reductions (f^2 / 4 px^2 per
  // halving) and the bilinear read (f^2 / 6) add, so every level's variance
  // stays sigma_i^2.
  const int n = params_.bands;
  std::vector<cv::Mat> levels(size_t(n) + 1);
  std::vector<int> factor(size_t(n) + 1, 1);
  levels[0] = image;
  double variance = 0.0;  // of the stored levels[i], full-resolution px^2
  for (int i = 1; i <= n; ++i) {
    const double sigma = sigmas_px_[size_t(i - 1)];
    int f = factor[size_t(i - 1)];
    const cv::Mat* from = &levels[size_t(i - 1)];
    cv::Mat reduced;
    if (params_.pyramid_from_px > 0 && sigma / (2 * f) >= params_.pyramid_from_px / 2 && from->cols >= 16 &&
        from->rows >= 16) {
      cv::resize(*from, reduced, cv::Size((from->cols + 1) / 2, (from->rows + 1) / 2), 0, 0, cv::INTER_AREA);
      variance += f * f / 4.0;
      f *= 2;
      from = &reduced;
    }
    factor[size_t(i)] = f;
    const double target = sigma * sigma - (f > 1 ? f * f / 6.0 : 0.0);
    const double extra = std::sqrt(std::max(target - variance, 0.0)) / f;  // at the level's own resolution
    if (extra < 0.05) {
      levels[size_t(i)] = from == &reduced ? reduced : from->clone();
    } else {
      cv::GaussianBlur(*from, levels[size_t(i)], cv::Size(0, 0), extra, extra, cv::BORDER_REPLICATE);
      variance = std::max(variance, target);
    }
  }
  std::vector<float> tau(tau_.begin(), tau_.end());
  cv::parallel_for_(cv::Range(0, image.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const float* lv = level.ptr<float>(y);
      cv::Vec3f* out = image.ptr<cv::Vec3f>(y);
      for (int x = 0; x < image.cols; ++x) {
        int k = 0;  // the first kept band (n: none kept)
        while (k < n && !(lv[x] > tau[size_t(k)])) ++k;
        if (k > 0) out[x] = sample(levels[size_t(k)], factor[size_t(k)], x, y);
      }
    }
  });
}

}  // namespace eyestream::retina
