#include "glare/wave_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <fftw3.h>
#include <mutex>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "glare/color_matching.hpp"
#include "glare/fftw_planner.hpp"

namespace eyestream::glare {

namespace {

constexpr int kSize = kWaveSamples;
constexpr int kWavelengths = 16;
constexpr int kSmoothCentre_px = 3;


// The far-field intensity of the aperture (fftshifted, kSize^2, CV_64F):
// one complex 2-D FFT by FFTW (one fixed FFTW_ESTIMATE plan, made for
// data of any alignment, as the host's allocator may give: the same result
// on any thread count).
cv::Mat far_field(const WaveAperture& aperture, const WaveState& state) {
  cv::Mat field = aperture_field(aperture, state);  // CV_64FC2: FFTW's complex layout
  CV_Assert(field.isContinuous() && field.rows == kSize && field.cols == kSize);
  auto* data = reinterpret_cast<fftw_complex*>(field.ptr<double>());
  static const fftw_plan plan = [data] {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    return fftw_plan_dft_2d(kSize, kSize, data, data, FFTW_FORWARD, FFTW_ESTIMATE | FFTW_UNALIGNED);
  }();
  fftw_execute_dft(plan, data, data);  // executing a plan is thread-safe
  // |F|^2, fftshifted: zero frequency to (kSize / 2, kSize / 2).
  cv::Mat shifted(kSize, kSize, CV_64F);
  const int h = kSize / 2;
  for (int y = 0; y < kSize; ++y) {
    const cv::Vec2d* in = field.ptr<cv::Vec2d>(y);
    double* out = shifted.ptr<double>((y + h) % kSize);
    for (int x = 0; x < kSize; ++x) out[(x + h) % kSize] = in[x][0] * in[x][0] + in[x][1] * in[x][1];
  }
  return shifted;
}

double bilinear(const cv::Mat& m, double x, double y) {
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  if (x0 < 0 || y0 < 0 || x0 + 1 >= m.cols || y0 + 1 >= m.rows) return 0.0;
  const double fx = x - x0, fy = y - y0;
  const double* a = m.ptr<double>(y0);
  const double* b = m.ptr<double>(y0 + 1);
  return (a[x0] * (1 - fx) + a[x0 + 1] * fx) * (1 - fy) + (b[x0] * (1 - fx) + b[x0 + 1] * fx) * fy;
}

}  // namespace

WavePattern wave_pattern(const WaveAperture& aperture, const WaveState& state, double ppd, int radius_px) {
  CV_Assert(aperture.samples == kSize && !aperture.fixed.empty());
  WavePattern p;
  p.pixels_per_degree = ppd;
  p.radius = std::max(0, std::min(radius_px, int(kWavePatternReach_deg * ppd)));
  cv::Mat intensity = far_field(aperture, state);
  // A pixel's footprint: the mean over it (a box of its width in bins, at 550 nm).
  const int box = int(std::lround(1.0 / ppd / kWaveBin_deg));
  if (box >= 2) cv::blur(intensity, intensity, cv::Size(box, box), cv::Point(-1, -1), cv::BORDER_CONSTANT);
  const int n = 2 * p.radius + 1;
  for (cv::Mat& m : p.rgb) m = cv::Mat::ones(n, n, CV_64F);
  cv::Vec3d weights[kWavelengths], total(0, 0, 0);
  double scale[kWavelengths];
  for (int j = 0; j < kWavelengths; ++j) {
    const double lambda = 400.0 + 300.0 * (j + 0.5) / kWavelengths;
    scale[j] = kWaveLambda0_nm / lambda;  // angle to the 550 nm pattern's
    weights[j] = rec709_rgb_sensitivity(lambda) * scale[j] * scale[j];
    total += rec709_rgb_sensitivity(lambda);
  }
  cv::parallel_for_(cv::Range(0, n), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y)
      for (int x = 0; x < n; ++x) {
        const double dx = x - p.radius, dy = y - p.radius;
        if (std::hypot(dx, dy) > p.radius) continue;
        cv::Vec3d v(0, 0, 0);
        for (int j = 0; j < kWavelengths; ++j) {
          const double u = dx / ppd / kWaveBin_deg * scale[j] + kSize / 2, w = dy / ppd / kWaveBin_deg * scale[j] + kSize / 2;
          v += weights[j] * bilinear(intensity, u, w);
        }
        for (int c = 0; c < 3; ++c) p.rgb[c].at<double>(y, x) = v[c] / total[c];
      }
  });
  // Each 1 px ring to mean 1; the centre smooth.
  for (cv::Mat& m : p.rgb) {
    std::vector<double> sum(size_t(p.radius) + 2, 0.0);
    std::vector<int> count(sum.size(), 0);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double r = std::hypot(x - p.radius, y - p.radius);
        if (r > p.radius) continue;
        sum[size_t(std::lround(r))] += m.at<double>(y, x), ++count[size_t(std::lround(r))];
      }
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double r = std::hypot(x - p.radius, y - p.radius);
        const size_t ring = size_t(std::lround(r));
        double& v = m.at<double>(y, x);
        if (r > p.radius || ring <= size_t(kSmoothCentre_px) || sum[ring] <= 0.0)
          v = 1.0;
        else
          v *= count[ring] / sum[ring];
      }
  }
  return p;
}

double pattern_correlation(const WavePattern& a, const WavePattern& b, double inner_deg, double outer_deg) {
  const int radius = std::min(a.radius, b.radius);
  double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
  int n = 0;
  for (int y = -radius; y <= radius; ++y)
    for (int x = -radius; x <= radius; ++x) {
      const double t = std::hypot(x, y) / a.pixels_per_degree;
      if (t < inner_deg || t > outer_deg) continue;
      const double u = a.rgb[1].at<double>(y + a.radius, x + a.radius) - 1.0;
      const double v = b.rgb[1].at<double>(y + b.radius, x + b.radius) - 1.0;
      sa += u, sb += v, saa += u * u, sbb += v * v, sab += u * v, ++n;
    }
  const double cov = sab / n - sa / n * sb / n;
  return cov / std::sqrt((saa / n - sa / n * sa / n) * (sbb / n - sb / n * sb / n));
}

}  // namespace eyestream::glare
