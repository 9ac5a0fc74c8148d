#include "glare/psf_kernel.hpp"

#include <cmath>
#include <vector>

#include "glare/color_matching.hpp"
#include "glare/flare_lines.hpp"
#include "glare/vos_psf.hpp"

namespace eyestream::glare {

namespace {

constexpr int kWavelengths = 50;
constexpr double kHaloTableStep = 0.002, kHaloTableEnd = 6.0;  // deg; f3 is 0 beyond ~5.5 deg

// Radial profiles of the halo for the three channels: sum over wavelengths
// of f3(t, lambda) s_c(lambda) / sum s_c(lambda), a mix of unit-volume rings.
std::vector<cv::Vec3d> halo_table() {
  std::vector<cv::Vec3d> table(size_t(kHaloTableEnd / kHaloTableStep) + 2, cv::Vec3d(0, 0, 0));
  cv::Vec3d total(0, 0, 0);
  for (int k = 0; k < kWavelengths; ++k) {
    const double lambda = 400.0 + 300.0 * (k + 0.5) / kWavelengths;
    const cv::Vec3d s = rec709_rgb_sensitivity(lambda);
    total += s;
    for (size_t i = 0; i < table.size(); ++i) table[i] += s * vos_f3(double(i) * kHaloTableStep, lambda);
  }
  for (cv::Vec3d& v : table)
    for (int c = 0; c < 3; ++c) v[c] /= total[c];
  return table;
}

cv::Vec3d halo_at(const std::vector<cv::Vec3d>& table, double t) {
  const double x = t / kHaloTableStep;
  const size_t i = size_t(x);
  if (i + 1 >= table.size()) return {0, 0, 0};
  const double f = x - double(i);
  return table[i] * (1.0 - f) + table[i + 1] * f;
}

}  // namespace

ComponentKernels build_component_kernels(int w, int h, double ppd, const EyeOptics& optics) {
  const std::function<double(double)> core = optics.component(0), inner = optics.component(1),
                                      outer = optics.component(2);
  ComponentKernels k;
  k.pixels_per_degree = ppd;
  const cv::Size size(2 * w - 1, 2 * h - 1);
  // Every value is written below, rows in parallel: no fill first (a
  // serial first touch of every page).
  k.core.create(size, CV_64F);
  k.inner.create(size, CV_64F);
  k.outer.create(size, CV_64F);
  for (cv::Mat& m : k.halo) m.create(size, CV_64F);
  const std::vector<cv::Vec3d> halo = halo_table();
  const int cx = w - 1, cy = h - 1;
  const double pixel_sr = std::pow(M_PI / 180.0 / ppd, 2.0);
  cv::parallel_for_(cv::Range(0, size.height), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y)
      for (int x = 0; x < size.width; ++x) {
        const double dx = x - cx, dy = y - cy, r = std::hypot(dx, dy), t_centre = r / ppd;
        const int n = r <= 3 ? 16 : (r <= 12 || (t_centre > 2.0 && t_centre < 4.5)) ? 4 : 1;
        double f0 = 0, f1 = 0, f2 = 0;
        cv::Vec3d f3(0, 0, 0);
        for (int sy = 0; sy < n; ++sy)
          for (int sx = 0; sx < n; ++sx) {
            const double t = std::hypot(dx + (sx + 0.5) / n - 0.5, dy + (sy + 0.5) / n - 0.5) / ppd;
            f0 += core(t);
            f1 += inner(t);
            f2 += outer(t);
            f3 += halo_at(halo, t);
          }
        // Mean density per steradian over the footprint, times the pixel's solid angle.
        const double weight = pixel_sr / (n * n);
        k.core.at<double>(y, x) = f0 * weight;
        k.inner.at<double>(y, x) = f1 * weight;
        k.outer.at<double>(y, x) = f2 * weight;
        for (int c = 0; c < 3; ++c) k.halo[c].at<double>(y, x) = f3[c] * weight;
      }
  });
  if (optics.flare_lines()) {
    const double frame_ppd = optics.frame_pixels_per_degree();
    apply_flare_lines(flare_lines(optics.viewer(), FlareKind::corona), ppd, {&k.inner, &k.outer}, frame_ppd);
    apply_flare_lines(flare_lines(optics.viewer(), FlareKind::halo), ppd, {&k.halo[0], &k.halo[1], &k.halo[2]},
                      frame_ppd);
  }
  return k;
}

cv::Mat combined_kernel(const ComponentKernels& k, const PsfWeights& w, int channel) {
  return k.core * w.core + k.inner * w.inner + k.outer * w.outer + k.halo[channel] * w.halo;
}

double energy_beyond(const PsfWeights& w, double t_deg) {
  auto psf = [&](double t) {
    return w.core * vos_f0(t) + w.inner * vos_f1(t) + w.outer * vos_f2(t) + w.halo * vos_f3(t, 568.0);
  };
  const double total = hemisphere_integral(psf);
  return hemisphere_integral([&](double t) { return t > t_deg ? psf(t) : 0.0; }) / total;
}

}  // namespace eyestream::glare
