#include "samples/night_city.hpp"

#include <cmath>
#include <opencv2/core.hpp>

#include "samples/draw.hpp"
#include "samples/scene_writer.hpp"

namespace eyestream::samples {

namespace {

double default_ppd(int width) { return width / 29.3; }  // the default viewing condition

struct Lamp {
  double x, y, radius;  // pixels
  cv::Vec3f rgb;        // cd/m^2
};

// The still part: sky, facades with windows, road, pavement, signs and
// lamps, drawn once (positions from the seed).
cv::Mat street(const SceneOptions& o, cv::RNG& rng, std::vector<Lamp>& lamps) {
  const int w = o.width, h = o.height;
  const double ppd = default_ppd(w);
  cv::Mat f(h, w, CV_32FC3, cv::Scalar(0.02f, 0.015f, 0.012f));                 // sky glow (warm city haze)
  paint_rect(f, 0, 0.62 * h, w, h, with_luminance({1.0f, 0.9f, 0.8f}, 0.4f));  // road, lit
  // Facades left and right, receding; windows in a grid, some lit.
  for (int side = 0; side < 2; ++side) {
    const double x0 = side == 0 ? 0.0 : 0.62 * w, x1 = side == 0 ? 0.38 * w : w;
    paint_rect(f, x0, 0.05 * h, x1, 0.62 * h, with_luminance({0.9f, 0.85f, 0.8f}, 0.08f));
    const double cell = 0.6 * ppd;
    for (double y = 0.08 * h; y + cell < 0.58 * h; y += cell)
      for (double x = x0 + 0.2 * cell; x + cell < x1; x += cell) {
        if (rng.uniform(0.0, 1.0) > 0.45) continue;  // dark window
        const float l = float(std::pow(10.0, rng.uniform(0.7, 2.2)));  // 5 to 160 cd/m^2
        const cv::Vec3f tint = rng.uniform(0.0, 1.0) < 0.7 ? cv::Vec3f(1.0f, 0.75f, 0.45f) : cv::Vec3f(0.8f, 0.9f, 1.0f);
        paint_rect(f, x, y, x + 0.55 * cell, y + 0.65 * cell, with_luminance(tint, l));
      }
  }
  // Neon signs: saturated bars of 300 to 3000 cd/m^2.
  const cv::Vec3f neon[4] = {{1.0f, 0.05f, 0.1f}, {0.1f, 1.0f, 0.3f}, {0.15f, 0.3f, 1.0f}, {1.0f, 0.3f, 0.9f}};
  for (int i = 0; i < 10; ++i) {
    const double x = rng.uniform(0.02, 0.98) * w, y = rng.uniform(0.15, 0.55) * h;
    if (x > 0.38 * w && x < 0.62 * w) continue;  // no facade there
    const double len = rng.uniform(0.5, 1.5) * ppd, thick = 0.06 * ppd;
    const bool vertical = rng.uniform(0.0, 1.0) < 0.5;
    paint_rect(f, x, y, x + (vertical ? thick : len), y + (vertical ? len : thick),
               with_luminance(neon[i % 4], float(std::pow(10.0, rng.uniform(2.5, 3.5)))));
  }
  // Street lamps along both kerbs (sodium amber and LED white), receding to
  // the vanishing point; traffic signals at the crossing ahead.
  const double vx = 0.5 * w, vy = 0.45 * h;
  for (int i = 0; i < 7; ++i) {
    const double depth = 1.0 / (1.0 + 0.6 * i);  // 1 near, small far
    for (int side : {-1, 1}) {
      const double x = vx + side * 0.45 * w * depth, y = vy - 0.30 * h * depth;
      const bool led = (i + (side > 0)) % 2 == 0;
      lamps.push_back({x, y, std::max(0.05 * ppd * depth, 0.3),
                       led ? cv::Vec3f(4e4f, 4.2e4f, 4.6e4f) : cv::Vec3f(3e4f, 1.6e4f, 3e3f)});
    }
  }
  for (int side : {-1, 1}) {
    lamps.push_back({vx + side * 0.05 * w, vy - 0.05 * h, 0.04 * ppd, {3e3f, 60.0f, 20.0f}});   // red
    lamps.push_back({vx + side * 0.05 * w, vy - 0.03 * h, 0.04 * ppd, {100.0f, 4e3f, 1.5e3f}});  // green
  }
  for (const Lamp& l : lamps) add_disc(f, l.x, l.y, l.radius, l.rgb);
  return f;
}

}  // namespace

void generate_night_city(const SceneOptions& o) {
  const double duration = o.duration_s > 0 ? o.duration_s : kNightCityDuration_s;
  const double ppd = default_ppd(o.width);
  cv::RNG rng(0x5eed0000ULL + o.seed);
  std::vector<Lamp> lamps;
  const cv::Mat still = street(o, rng, lamps);
  SceneWriter writer(o.out_dir, o.fps, 50.0);
  const int frames = std::max(1, int(std::lround(duration * o.fps)));
  const double vx = 0.5 * o.width, vy = 0.45 * o.height;
  for (int i = 0; i < frames; ++i) {
    const double t = i / o.fps;
    cv::Mat f = still.clone();
    // Two cars: one approaching (headlights growing to 5e4 cd/m^2), one
    // leaving (red tail lights), each along its lane.
    const double a = std::fmod(t / 4.0, 1.0), b = std::fmod(t / 5.0 + 0.3, 1.0);
    const double near_a = 0.08 + 0.92 * a * a, near_b = 1.0 - 0.9 * b;
    for (double side : {-1.0, 1.0}) {
      add_disc(f, vx - 0.12 * o.width * near_a + side * 0.05 * o.width * near_a, vy + 0.2 * o.height * near_a,
               std::max(0.06 * ppd * near_a, 0.3), cv::Vec3f(5e4f, 5e4f, 5.5e4f));
      add_disc(f, vx + 0.12 * o.width * near_b + side * 0.05 * o.width * near_b, vy + 0.2 * o.height * near_b,
               std::max(0.05 * ppd * near_b, 0.3), cv::Vec3f(800.0f, 20.0f, 10.0f));
    }
    writer.add_frame(f);
  }
  // The gaze: fixations of 0.2-0.6 s on lights, windows and the road, joined
  // by 40 ms saccades; a blink at 40 % of the way.
  std::vector<io::GazeSample> gaze;
  const double rate = 120.0;
  double x = vx, y = vy + 0.1 * o.height, t = 0.0;
  while (t < duration) {
    const double fix = rng.uniform(0.2, 0.6);
    for (double u = 0; u < fix && t < duration; u += 1.0 / rate, t += 1.0 / rate)
      gaze.push_back({t, x, y, std::abs(t - 0.4 * duration) < 0.08 ? io::EyeState::kClosed : io::EyeState::kOpen});
    const bool on_lamp = rng.uniform(0.0, 1.0) < 0.35;
    const Lamp& l = lamps[size_t(rng.uniform(0, int(lamps.size())))];
    const double nx = on_lamp ? l.x : rng.uniform(0.1, 0.9) * o.width;
    const double ny = on_lamp ? l.y : rng.uniform(0.15, 0.8) * o.height;
    for (double u = 0; u < 0.04 && t < duration; u += 1.0 / rate, t += 1.0 / rate) {
      const double k = u / 0.04;
      gaze.push_back({t, x + (nx - x) * k, y + (ny - y) * k, io::EyeState::kOpen});
    }
    x = nx, y = ny;
  }
  writer.finish(gaze);
}

}  // namespace eyestream::samples
