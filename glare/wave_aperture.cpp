#include "glare/wave_aperture.hpp"

#include <cmath>

namespace eyestream::glare {

WaveAperture wave_aperture(std::int64_t seed, double side_mm, int n) {
  cv::RNG rng(0x3a7e0000ULL ^ std::uint64_t(seed) * 0x9e3779b97f4a7c15ULL);
  WaveAperture a;
  const auto disc_point = [&](double radius, double& x, double& y) {
    const double r = radius * std::sqrt(rng.uniform(0.0, 1.0)), phi = rng.uniform(0.0, 2.0 * M_PI);
    x = r * std::cos(phi), y = r * std::sin(phi);
  };
  for (int i = 0; i < 180; ++i) {
    WaveParticle p{};
    disc_point(4.0, p.x_mm, p.y_mm);
    const bool lens = i < 120;
    p.depth_mm = lens ? rng.uniform(0.5, 4.0) : rng.uniform(4.0, 16.0);
    p.radius_mm = lens ? rng.uniform(0.003, 0.008) : rng.uniform(0.005, 0.015);
    if (!lens) {
      const double speed = rng.uniform(0.0, 0.02), heading = rng.uniform(0.0, 2.0 * M_PI);
      p.vx_mm_s = speed * std::cos(heading), p.vy_mm_s = speed * std::sin(heading);
    }
    a.particles.push_back(p);
  }
  for (int i = 0; i < int(5.0 / WaveAperture::kFibreBand_mm) + 1; ++i) a.band_offsets.push_back(rng.uniform(0.0, 2.0 * M_PI));
  // The disc with its soft rim (its last 5 %) and the fibres' phase.
  a.side_mm = side_mm;
  a.samples = n;
  a.fixed = cv::Mat(n, n, CV_64FC2);
  const double dx = side_mm / n, x0 = -0.5 * side_mm + 0.5 * dx, disc_r = 0.25 * side_mm;
  const double k = 2.0 * M_PI / WaveAperture::kFibrePeriod_mm;  // fibres per mm of circle, times 2 pi
  cv::parallel_for_(cv::Range(0, n), [&](const cv::Range& rows) {
    for (int r = rows.start; r < rows.end; ++r) {
      cv::Vec2d* row = a.fixed.ptr<cv::Vec2d>(r);
      const double y = x0 + r * dx;
      for (int c = 0; c < n; ++c) {
        const double x = x0 + c * dx, rho = std::hypot(x, y), u = rho / disc_r;
        if (u >= 1.0) {
          row[c] = {0.0, 0.0};
          continue;
        }
        const double rim = u > 0.95 ? 0.5 + 0.5 * std::cos(M_PI * (u - 0.95) / 0.05) : 1.0;
        // Fibres run radially: band b holds a whole number of them round its circle.
        const size_t band = std::min(a.band_offsets.size() - 1, size_t(rho / WaveAperture::kFibreBand_mm));
        const double fibres = std::round(k * (double(band) + 0.5) * WaveAperture::kFibreBand_mm);
        const double phase = a.fibre_phase_rad * std::cos(fibres * (std::atan2(y, x) + a.band_offsets[band]));
        row[c] = {rim * std::cos(phase), rim * std::sin(phase)};
      }
    }
  });
  return a;
}

cv::Mat aperture_field(const WaveAperture& a, const WaveState& s) {
  const int n = a.samples;
  const double dx = a.side_mm / n, x0 = -0.5 * a.side_mm + 0.5 * dx;
  const double shrink = 0.5 * a.side_mm / s.pupil_mm;  // shrunk mm per true mm
  // Stiles-Crawford: amplitude 10^(-0.025 r^2), r in true mm; separable.
  std::vector<double> sc(size_t(n), 0.0);
  for (int i = 0; i < n; ++i) sc[size_t(i)] = std::pow(10.0, -0.025 * std::pow((x0 + i * dx) / shrink, 2.0));
  cv::Mat out(n, n, CV_64FC2);
  cv::parallel_for_(cv::Range(0, n), [&](const cv::Range& rows) {
    for (int r = rows.start; r < rows.end; ++r) {
      const cv::Vec2d* in = a.fixed.ptr<cv::Vec2d>(r);
      cv::Vec2d* o = out.ptr<cv::Vec2d>(r);
      for (int c = 0; c < n; ++c) o[c] = in[c] * (sc[size_t(r)] * sc[size_t(c)]);
    }
  });
  // The particles' shadows, where this light meets them, inside the pupil.
  const double tx = std::tan(s.light_x_deg * M_PI / 180.0), ty = std::tan(s.light_y_deg * M_PI / 180.0);
  for (const WaveParticle& p : a.particles) {
    const double true_x = p.x_mm + p.vx_mm_s * s.time_s + p.depth_mm * tx;
    const double true_y = p.y_mm + p.vy_mm_s * s.time_s + p.depth_mm * ty;
    if (std::hypot(true_x, true_y) > 0.5 * s.pupil_mm) continue;
    const double px = true_x * shrink, py = true_y * shrink;
    const int c0 = int(std::floor((px - p.radius_mm - x0) / dx)), c1 = int(std::ceil((px + p.radius_mm - x0) / dx));
    const int r0 = int(std::floor((py - p.radius_mm - x0) / dx)), r1 = int(std::ceil((py + p.radius_mm - x0) / dx));
    for (int r = std::max(r0, 0); r <= std::min(r1, n - 1); ++r)
      for (int c = std::max(c0, 0); c <= std::min(c1, n - 1); ++c)
        if (std::hypot(x0 + c * dx - px, x0 + r * dx - py) <= p.radius_mm) out.at<cv::Vec2d>(r, c) = {0.0, 0.0};
  }
  return out;
}

}  // namespace eyestream::glare
