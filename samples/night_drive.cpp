// A night road seen from a driver's seat, rendered by a pinhole camera whose
// horizontal field of view matches eyestream's default viewing geometry
// (29.3 deg), so geometry and glare sizes agree with the default run.
//
// Luminances (cd/m^2), chosen to be physically plausible:
// - sky 0.003 at the zenith to 0.02 at the horizon, bluish; stars 1-5 (sub-pixel);
// - verge 0.02 x lamp light; asphalt lit by the lamps: L = q E with luminance
//   coefficient q = 0.07 /sr (dry asphalt, CIE R3 class order of magnitude)
//   and E = I cos(theta) / d^2 from 2000 cd lamps 8 m high every 35 m,
//   giving ~2 cd/m^2 under a lamp and ~0.2 between lamps; lane markings 3x;
// - lamp heads: 2000 cd over a 0.3 m-radius disc, ~7000 cd/m^2, sodium orange;
// - the oncoming car's headlights: 1e5 cd/m^2 discs of 9 cm radius, 1.4 m
//   apart, approaching from 220 m to 10 m: sub-pixel points at first, drawn
//   by energy (see draw.hpp), then discs over ten pixels wide.
#include "samples/night_drive.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "samples/draw.hpp"
#include "samples/scene_writer.hpp"

namespace eyestream::samples {

namespace {

constexpr double kFovDeg = 29.3;  // matches the default viewing geometry
constexpr double kEyeHeight_m = 1.2;
constexpr double kOwnLaneX_m = 1.75;  // camera x; road centre at 0
constexpr double kRoadHalfWidth_m = 3.5;
constexpr double kSpeed_m_s = 15.0;
constexpr double kLampX_m = 5.0, kLampHeight_m = 8.0, kLampSpacing_m = 35.0, kLampIntensity_cd = 2000.0;
constexpr double kLampRadius_m = 0.3;
constexpr double kAsphaltQ_per_sr = 0.07;
constexpr double kCarStartZ_m = 220.0, kCarEndZ_m = 10.0;
constexpr double kHeadlightLuminance = 1e5, kHeadlightRadius_m = 0.09, kHeadlightHeight_m = 0.7;
constexpr double kHeadlightHalfSpacing_m = 0.7, kCarLaneX_m = -1.75;

const cv::Vec3f kSodium(1.0f, 0.62f, 0.22f), kSky(0.55f, 0.7f, 1.2f), kVerge(0.7f, 0.9f, 0.6f);
const cv::Vec3f kAsphalt(1.0f, 1.0f, 1.0f), kXenon(0.95f, 1.0f, 1.1f);

struct Camera {
  double f_px, cx, horizon_v;
  double project_u(double x_w, double z) const { return cx + f_px * (x_w - kOwnLaneX_m) / z; }
  double project_v(double height_m, double z) const { return horizon_v + f_px * (kEyeHeight_m - height_m) / z; }
};

// Illuminance (lux) on the road at world (x, z) from the lamps, z relative to the camera.
double lamp_illuminance(double x, double z, double travelled_m) {
  double e = 0.0;
  const double phase = std::fmod(travelled_m, kLampSpacing_m);
  for (int k = -1; k < 12; ++k) {
    const double lz = k * kLampSpacing_m - phase + 10.0;
    const double dx = x - kLampX_m, dz = z - lz, h = kLampHeight_m;
    const double d2 = dx * dx + dz * dz + h * h;
    e += kLampIntensity_cd * (h / std::sqrt(d2)) / d2;
  }
  return e;
}

cv::Vec3f ground(double x, double z, double travelled_m) {
  const double lamp = kAsphaltQ_per_sr * lamp_illuminance(x, z, travelled_m);
  // Own low beams: a pool ahead in the own lane.
  const double own = 1.5 * std::exp(-std::pow((z - 15.0) / 15.0, 2)) * std::exp(-std::pow(x - kOwnLaneX_m, 2) / 8.0);
  const double ax = std::abs(x);
  if (ax > kRoadHalfWidth_m) return with_luminance(kVerge, float(0.3 * (lamp + own) + 0.005));
  const bool edge_line = ax > kRoadHalfWidth_m - 0.15;
  const bool centre_dash = ax < 0.075 && std::fmod(z + travelled_m, 12.0) < 4.0;
  const double mark = (edge_line || centre_dash) ? 3.0 : 1.0;
  return with_luminance(kAsphalt, float(mark * (lamp + own) + 0.01)) * 0.5f +
         with_luminance(kSodium, float(mark * lamp)) * 0.5f;
}

void render_background(cv::Mat& frame, const Camera& cam, double travelled_m) {
  cv::parallel_for_(cv::Range(0, frame.rows), [&](const cv::Range& rows) {
    for (int v = rows.start; v < rows.end; ++v) {
      cv::Vec3f* row = frame.ptr<cv::Vec3f>(v);
      const double dv = v + 0.5 - cam.horizon_v;
      for (int u = 0; u < frame.cols; ++u) {
        if (dv <= 0) {
          row[u] = with_luminance(kSky, float(0.003 + 0.017 * std::exp(dv / (0.12 * frame.rows))));
        } else {
          const double z = cam.f_px * kEyeHeight_m / dv;
          const double x = kOwnLaneX_m + (u + 0.5 - cam.cx) * z / cam.f_px;
          row[u] = ground(x, z, travelled_m);
        }
      }
    }
  });
}

void render_lamps(cv::Mat& frame, const Camera& cam, double travelled_m) {
  const double phase = std::fmod(travelled_m, kLampSpacing_m);
  const cv::Vec3f head = with_luminance(kSodium, float(kLampIntensity_cd / (M_PI * kLampRadius_m * kLampRadius_m)));
  for (int k = 0; k < 12; ++k) {
    const double z = k * kLampSpacing_m - phase + 10.0;
    if (z < 2.0) continue;
    add_disc(frame, cam.project_u(kLampX_m, z), cam.project_v(kLampHeight_m, z), cam.f_px * kLampRadius_m / z, head);
  }
}

double car_z(double t, double duration) {
  return kCarStartZ_m + (kCarEndZ_m - kCarStartZ_m) * std::clamp(t / duration, 0.0, 1.0);
}

cv::Point2d headlight_centre(const Camera& cam, double z) {
  return {cam.project_u(kCarLaneX_m, z), cam.project_v(kHeadlightHeight_m, z)};
}

void render_car(cv::Mat& frame, const Camera& cam, double z) {
  const cv::Vec3f light = with_luminance(kXenon, float(kHeadlightLuminance));
  for (double side : {-1.0, 1.0})
    add_disc(frame, cam.project_u(kCarLaneX_m + side * kHeadlightHalfSpacing_m, z),
             cam.project_v(kHeadlightHeight_m, z), cam.f_px * kHeadlightRadius_m / z, light);
}

std::vector<cv::Vec3f> star_field(const cv::Size& size, const Camera& cam, std::uint64_t seed,
                                  std::vector<cv::Point2d>& at) {
  std::mt19937_64 rng(seed ^ 0x5eedULL);
  std::uniform_real_distribution<double> ux(0, size.width), uy(0, cam.horizon_v * 0.9), ul(1.0, 5.0);
  std::vector<cv::Vec3f> colour;
  for (int i = 0; i < 40; ++i) {
    at.emplace_back(ux(rng), uy(rng));
    colour.push_back(with_luminance(cv::Vec3f(1, 1, 1), float(ul(rng))));
  }
  return colour;
}

// The driver looks at the road 40 m ahead, glances at the headlights from
// 2.4 s to 3.8 s (pursuing them), looks back, and blinks at 5.0-5.15 s.
std::vector<io::GazeSample> gaze_log(const Camera& cam, double duration, std::uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0x6a2eULL);
  std::normal_distribution<double> jitter(0.0, 0.6);
  const double rate_hz = 120.0;
  const cv::Point2d road(cam.project_u(kOwnLaneX_m, 40.0), cam.project_v(0.0, 40.0));
  const double scale = duration / kNightDriveDuration_s;
  const double glance0 = 2.4 * scale, glance1 = 3.8 * scale, blink0 = 5.0 * scale, saccade = 0.05;
  std::vector<io::GazeSample> out;
  for (int i = 0; i < int(duration * rate_hz); ++i) {
    const double t = i / rate_hz;
    io::GazeSample s;
    s.t_s = t;
    cv::Point2d lights = headlight_centre(cam, car_z(t, duration));
    cv::Point2d p = road;
    if (t >= glance0 && t < glance1) {
      const double a = std::min((t - glance0) / saccade, 1.0);
      p = road + (lights - road) * a;
    } else if (t >= glance1 && t < glance1 + saccade) {
      const double a = (t - glance1) / saccade;
      p = lights + (road - lights) * a;
    }
    s.x = p.x + jitter(rng);
    s.y = p.y + jitter(rng);
    if (t >= blink0 && t < blink0 + 0.15) s.state = io::EyeState::kClosed;
    out.push_back(s);
  }
  return out;
}

}  // namespace

void generate_night_drive(const SceneOptions& o) {
  const double duration = o.duration_s > 0 ? o.duration_s : kNightDriveDuration_s;
  const int frames = std::max(1, int(std::lround(duration * o.fps)));
  Camera cam{(o.width / 2.0) / std::tan(kFovDeg * M_PI / 360.0), o.width / 2.0, o.height * 0.42};
  std::vector<cv::Point2d> star_at;
  const std::vector<cv::Vec3f> star_colour = star_field(cv::Size(o.width, o.height), cam, o.seed, star_at);
  SceneWriter writer(o.out_dir, o.fps, 10.0);
  cv::Mat frame(o.height, o.width, CV_32FC3);
  for (int i = 0; i < frames; ++i) {
    const double t = i / o.fps;
    const double travelled = kSpeed_m_s * t;
    render_background(frame, cam, travelled);
    for (size_t s = 0; s < star_at.size(); ++s) add_disc(frame, star_at[s].x, star_at[s].y, 0.3, star_colour[s]);
    render_lamps(frame, cam, travelled);
    render_car(frame, cam, car_z(t, duration));
    writer.add_frame(frame);
  }
  writer.finish(gaze_log(cam, duration, o.seed));
}

}  // namespace eyestream::samples
