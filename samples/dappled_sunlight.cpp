#include "samples/dappled_sunlight.hpp"

#include <cmath>
#include <opencv2/core.hpp>

#include "samples/chaos_fluctuation.hpp"
#include "samples/draw.hpp"
#include "samples/fixed_gaze.hpp"
#include "samples/scene_writer.hpp"

namespace eyestream::samples {

namespace {

double default_ppd(int width) { return width / 29.3; }  // the default viewing condition

std::uint64_t gap_seed(std::uint64_t seed, int i) { return 0xd1ed5000ULL + seed * 1000003ULL + std::uint64_t(i); }

// The canopy without the sun: leaves lit from behind, patches of sky.
cv::Mat canopy(const SceneOptions& o, cv::RNG& rng) {
  const double ppd = default_ppd(o.width);
  cv::Mat f(o.height, o.width, CV_32FC3, cv::Scalar::all(0.0f));
  paint_rect(f, 0, 0, o.width, o.height, with_luminance({0.45f, 0.55f, 0.25f}, 120.0f));
  for (int i = 0; i < 40; ++i) {  // sky between the branches
    const double x = rng.uniform(0.0, 1.0) * o.width, y = rng.uniform(0.0, 0.7) * o.height;
    const double s = rng.uniform(0.3, 1.2) * ppd;
    paint_rect(f, x, y, x + s, y + 0.6 * s, with_luminance({0.75f, 0.85f, 1.0f}, 3000.0f));
  }
  for (int i = 0; i < 400; ++i) {  // leaves over the sky and each other
    const double x = rng.uniform(0.0, 1.0) * o.width, y = rng.uniform(0.0, 1.0) * o.height;
    const double s = rng.uniform(0.15, 0.5) * ppd;
    const float l = float(rng.uniform(100.0, 600.0));
    const cv::Vec3f tint = rng.uniform(0.0, 1.0) < 0.6 ? cv::Vec3f(0.5f, 0.7f, 0.2f) : cv::Vec3f(0.7f, 0.75f, 0.25f);
    paint_rect(f, x, y, x + s, y + 0.7 * s, with_luminance(tint, l));
  }
  return f;
}

}  // namespace

std::vector<std::vector<double>> sun_gap_fluctuations(std::uint64_t seed, int steps) {
  std::vector<std::vector<double>> s(kSunGaps, std::vector<double>(size_t(std::max(steps, 0))));
  for (int i = 0; i < kSunGaps; ++i) {
    ChaosFluctuation orbit(gap_seed(seed, i));
    for (int k = 0; k < steps; ++k) s[size_t(i)][size_t(k)] = orbit.next();
  }
  return s;
}

void generate_dappled_sunlight(const SceneOptions& o) {
  const double duration = o.duration_s > 0 ? o.duration_s : kDappledSunlightDuration_s;
  const double sun = o.luminance_cd_m2 > 0 ? o.luminance_cd_m2 : kSunLuminance_cd_m2;
  const double ppd = default_ppd(o.width);
  cv::RNG rng(0x1eaf0000ULL + o.seed);
  const cv::Mat still = canopy(o, rng);
  // The gaps: where they rest, and how much of the sun's disc each shows
  // (radius 0.02-0.08 deg: leaves hide most of its 0.27 deg).
  struct Gap {
    double x, y, radius_px, phase;
  };
  std::vector<Gap> gaps;
  for (int i = 0; i < kSunGaps; ++i)
    gaps.push_back({rng.uniform(0.15, 0.85) * o.width, rng.uniform(0.1, 0.6) * o.height,
                    rng.uniform(0.02, 0.08) * ppd, rng.uniform(0.0, 2.0 * M_PI)});
  const int frames = std::max(1, int(std::lround(duration * o.fps)));
  const int steps = int(std::floor((frames - 1) / o.fps * kWindClock_hz + 1e-9)) + 1;
  const std::vector<std::vector<double>> light = sun_gap_fluctuations(o.seed, steps);
  ChaosFluctuation gust(gap_seed(o.seed, kSunGaps));
  std::vector<double> sway(static_cast<size_t>(steps));
  double smooth = 0.0;
  for (int k = 0; k < steps; ++k) sway[size_t(k)] = smooth += 0.1 * ((2.0 * gust.next() - 1.0) - smooth);
  SceneWriter writer(o.out_dir, o.fps, std::max(3e4, sun / 6e4));  // half floats up to 65504 white
  for (int n = 0; n < frames; ++n) {
    const int k = int(std::floor(n / o.fps * kWindClock_hz + 1e-9));
    cv::Mat f = still.clone();
    for (int i = 0; i < kSunGaps; ++i) {
      const Gap& g = gaps[size_t(i)];
      // The wind: 0.3 deg with the gust, 0.1 deg of each leaf's own flutter.
      const double dx = (0.3 * sway[size_t(k)] + 0.1 * std::sin(2.0 * M_PI * 0.7 * k / kWindClock_hz + g.phase)) * ppd;
      const double dy = 0.1 * std::cos(2.0 * M_PI * 0.5 * k / kWindClock_hz + g.phase) * ppd;
      add_disc(f, g.x + dx, g.y + dy, g.radius_px, cv::Vec3f::all(float(sun * light[size_t(i)][size_t(k)])));
    }
    writer.add_frame(f);
  }
  writer.finish(fixed_gaze(0.5 * o.width, 0.65 * o.height, duration, 120.0));
}

}  // namespace eyestream::samples
