#include "glare/wave_aperture.hpp"

#include <algorithm>
#include <cmath>

namespace eyestream::glare {

namespace {

// The lashes of the upper lid (wave_aperture.hpp), from their own stream
// of the viewer's seed.
std::vector<WaveLash> upper_lashes(std::int64_t seed) {
  cv::RNG rng(0x1a5e0000ULL ^ std::uint64_t(seed) * 0x9e3779b97f4a7c15ULL);
  std::vector<WaveLash> lashes;
  constexpr double kSpan_mm = 12.0, kPerMm = 4.0;
  constexpr double kDeg = M_PI / 180.0;
  for (int i = 0; i < int(kSpan_mm * kPerMm); ++i) {
    WaveLash l{};
    l.root_x_mm = -0.5 * kSpan_mm + (i + rng.uniform(0.0, 1.0)) / kPerMm;
    l.root_depth_mm = WaveAperture::kLidDepth_mm - rng.uniform(0.0, 0.6);  // two rows, about 0.3 mm apart
    const double length = rng.uniform(8.0, 11.0);
    const double droop = rng.uniform(10.0, 25.0) * kDeg, rise = rng.uniform(20.0, 45.0) * kDeg;
    l.tan_side = std::tan(rng.uniform(-12.0, 12.0) * kDeg);
    l.tan_droop = std::tan(droop);
    l.forward_mm = 0.85 * length;
    // The slope tan(droop) - 2 curl s is -tan(rise) at the tip.
    l.curl_per_mm = (std::tan(droop) + std::tan(rise)) / (2.0 * l.forward_mm);
    l.width_mm = rng.uniform(0.07, 0.12);
    lashes.push_back(l);
  }
  return lashes;
}

// Multiplies the samples of `field` within half_width_mm of the segment a-b
// (field mm) by how far outside they lie, softened over one sample dx.
void occlude_segment(cv::Mat& field, double x0, double dx, cv::Point2d a, cv::Point2d b, double half_width_mm) {
  const int n = field.rows;
  const double reach = half_width_mm + dx;
  const int c0 = std::max(0, int(std::floor((std::min(a.x, b.x) - reach - x0) / dx)));
  const int c1 = std::min(n - 1, int(std::ceil((std::max(a.x, b.x) + reach - x0) / dx)));
  const int r0 = std::max(0, int(std::floor((std::min(a.y, b.y) - reach - x0) / dx)));
  const int r1 = std::min(n - 1, int(std::ceil((std::max(a.y, b.y) + reach - x0) / dx)));
  const cv::Point2d ab = b - a;
  const double length2 = ab.dot(ab);
  for (int r = r0; r <= r1; ++r) {
    cv::Vec2d* row = field.ptr<cv::Vec2d>(r);
    for (int c = c0; c <= c1; ++c) {
      const cv::Point2d p(x0 + c * dx, x0 + r * dx);
      const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
      const cv::Point2d d = p - (a + t * ab);
      const double outside = std::clamp((std::hypot(d.x, d.y) - half_width_mm) / dx + 0.5, 0.0, 1.0);
      row[c] *= outside;
    }
  }
}

}  // namespace

WaveAperture wave_aperture(std::int64_t seed, double side_mm, int n, double eyelid_mrd1_mm) {
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
  if (eyelid_mrd1_mm > 0.0) {
    a.eyelid_mrd1_mm = eyelid_mrd1_mm;
    a.lashes = upper_lashes(seed);
  }
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
  if (a.eyelid_mrd1_mm > 0.0) {
    // The lid: opaque above its margin's shadow (y down), softened over a sample.
    const double margin = (-a.eyelid_mrd1_mm + WaveAperture::kLidDepth_mm * ty) * shrink;
    for (int r = 0; r < n; ++r) {
      const double open = std::clamp((x0 + r * dx - margin) / dx + 0.5, 0.0, 1.0);
      if (open < 1.0) out.row(r) *= open;
    }
    // The lashes, each a chain of short segments.
    constexpr int kPieces = 12;
    for (const WaveLash& l : a.lashes) {
      const auto at = [&](double s) {
        const double depth = l.root_depth_mm - s;
        const double x = l.root_x_mm + s * l.tan_side + depth * tx;
        const double y = -a.eyelid_mrd1_mm + s * l.tan_droop - l.curl_per_mm * s * s + depth * ty;
        return cv::Point2d(x * shrink, y * shrink);
      };
      cv::Point2d from = at(0.0);
      for (int i = 1; i <= kPieces; ++i) {
        const cv::Point2d to = at(l.forward_mm * i / kPieces);
        occlude_segment(out, x0, dx, from, to, 0.5 * l.width_mm * shrink);
        from = to;
      }
    }
  }
  return out;
}

}  // namespace eyestream::glare
