#include "samples/night_road.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "samples/draw.hpp"
#include "samples/scene_writer.hpp"

namespace eyestream::samples {

namespace {

constexpr double kFovDeg = 29.3;  // matches the default viewing geometry
constexpr double kEyeHeight_m = 1.2;
constexpr double kLampRadius_m = 0.3;
constexpr double kAsphaltQ_per_sr = 0.07;

const cv::Vec3f kSodium(1.0f, 0.62f, 0.22f), kSky(0.55f, 0.7f, 1.2f), kVerge(0.7f, 0.9f, 0.6f);
const cv::Vec3f kAsphalt(1.0f, 1.0f, 1.0f), kXenon(0.95f, 1.0f, 1.1f);

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

void render_background(cv::Mat& frame, const RoadCamera& cam, double travelled_m) {
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

void render_lamps(cv::Mat& frame, const RoadCamera& cam, double travelled_m) {
  const double phase = std::fmod(travelled_m, kLampSpacing_m);
  const cv::Vec3f head = with_luminance(kSodium, float(kLampIntensity_cd / (M_PI * kLampRadius_m * kLampRadius_m)));
  for (int k = 0; k < 12; ++k) {
    const double z = k * kLampSpacing_m - phase + 10.0;
    if (z < 2.0) continue;
    add_disc(frame, cam.project_u(kLampX_m, z), cam.project_v(kLampHeight_m, z), cam.f_px * kLampRadius_m / z, head);
  }
}

}  // namespace

RoadCamera::RoadCamera(int width, int height)
    : f_px((width / 2.0) / std::tan(kFovDeg * M_PI / 360.0)), cx(width / 2.0), horizon_v(height * 0.42) {}

double RoadCamera::project_u(double x_w, double z) const { return cx + f_px * (x_w - kOwnLaneX_m) / z; }

double RoadCamera::project_v(double height_m, double z) const {
  return horizon_v + f_px * (kEyeHeight_m - height_m) / z;
}

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

void render_road(cv::Mat& frame, const RoadCamera& cam, double travelled_m, const StarField& stars) {
  render_background(frame, cam, travelled_m);
  stars.render(frame);
  render_lamps(frame, cam, travelled_m);
}

cv::Point2d headlight_centre(const RoadCamera& cam, double z) {
  return {cam.project_u(kCarLaneX_m, z), cam.project_v(kHeadlightHeight_m, z)};
}

void render_headlights(cv::Mat& frame, const RoadCamera& cam, double z) {
  const cv::Vec3f light = with_luminance(kXenon, float(kHeadlightLuminance));
  for (double side : {-1.0, 1.0})
    add_disc(frame, cam.project_u(kCarLaneX_m + side * kHeadlightHalfSpacing_m, z),
             cam.project_v(kHeadlightHeight_m, z), cam.f_px * kHeadlightRadius_m / z, light);
}

StarField::StarField(const cv::Size& size, const RoadCamera& cam, std::uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0x5eedULL);
  std::uniform_real_distribution<double> ux(0, size.width), uy(0, cam.horizon_v * 0.9), ul(1.0, 5.0);
  for (int i = 0; i < 40; ++i) {
    at_.emplace_back(ux(rng), uy(rng));
    colour_.push_back(with_luminance(cv::Vec3f(1, 1, 1), float(ul(rng))));
  }
}

void StarField::render(cv::Mat& frame) const {
  for (size_t s = 0; s < at_.size(); ++s) add_disc(frame, at_[s].x, at_[s].y, 0.3, colour_[s]);
}

std::vector<io::GazeSample> drive_gaze_log(const std::vector<Fixation>& fixations, const std::vector<double>& blinks_s,
                                           double duration_s, std::uint64_t seed,
                                           const std::function<cv::Point2d(Look, double)>& where,
                                           double blink_length_s) {
  std::mt19937_64 rng(seed ^ 0x6a2eULL);
  std::normal_distribution<double> jitter(0.0, 0.6);
  const double rate_hz = 120.0, saccade_s = 0.05;
  std::vector<io::GazeSample> out;
  size_t k = 0;
  for (int i = 0; i < int(duration_s * rate_hz); ++i) {
    const double t = i / rate_hz;
    while (k + 1 < fixations.size() && t >= fixations[k + 1].start_s) ++k;
    cv::Point2d p = where(fixations[k].look, t);
    if (k > 0 && t < fixations[k].start_s + saccade_s) {
      const cv::Point2d from = where(fixations[k - 1].look, t);
      p = from + (p - from) * ((t - fixations[k].start_s) / saccade_s);
    }
    io::GazeSample s;
    s.t_s = t;
    s.x = p.x + jitter(rng);
    s.y = p.y + jitter(rng);
    for (double b : blinks_s)
      if (t >= b && t < b + blink_length_s) s.state = io::EyeState::kClosed;
    out.push_back(s);
  }
  return out;
}

void write_drive(const SceneOptions& o, double default_duration_s, double speed_m_s, const DriveExtras& extras,
                 const DriveGaze& gaze) {
  const double duration = o.duration_s > 0 ? o.duration_s : default_duration_s;
  const int frames = std::max(1, int(std::lround(duration * o.fps)));
  const RoadCamera cam(o.width, o.height);
  const StarField stars(cv::Size(o.width, o.height), cam, o.seed);
  SceneWriter writer(o.out_dir, o.fps, 10.0);
  cv::Mat frame(o.height, o.width, CV_32FC3);
  for (int i = 0; i < frames; ++i) {
    const double t = i / o.fps;
    render_road(frame, cam, speed_m_s * t, stars);
    const cv::Mat mask = extras(frame, cam, t, duration);
    writer.add_frame(frame, mask);
  }
  writer.finish(gaze(cam, duration));
}

}  // namespace eyestream::samples
