// The `night-drive` scene: six seconds on the night road (night_road.hpp)
// at 15 m/s with an oncoming car approaching from 220 m to 10 m.
#include "samples/night_drive.hpp"

#include <algorithm>
#include <cmath>

#include "samples/night_road.hpp"

namespace eyestream::samples {

namespace {

constexpr double kSpeed_m_s = 15.0;
constexpr double kCarStartZ_m = 220.0, kCarEndZ_m = 10.0;

double car_z(double t, double duration) {
  return kCarStartZ_m + (kCarEndZ_m - kCarStartZ_m) * std::clamp(t / duration, 0.0, 1.0);
}

}  // namespace

void generate_night_drive(const SceneOptions& o) {
  auto headlights = [](cv::Mat& frame, const RoadCamera& cam, double t, double duration) {
    render_headlights(frame, cam, car_z(t, duration));
    return cv::Mat();
  };
  // The driver looks at the road 40 m ahead, glances at the headlights
  // from 2.4 s to 3.8 s (pursuing them), looks back, and blinks at 5.0 s
  // (times scaled with --duration).
  auto gaze = [&](const RoadCamera& cam, double duration) {
    const double scale = duration / kNightDriveDuration_s;
    const cv::Point2d road(cam.project_u(kOwnLaneX_m, 40.0), cam.project_v(0.0, 40.0));
    auto where = [&](Look look, double t) {
      return look == Look::kRoad ? road : headlight_centre(cam, car_z(t, duration));
    };
    return drive_gaze_log({{0.0, Look::kRoad}, {2.4 * scale, Look::kHeadlights}, {3.8 * scale, Look::kRoad}},
                          {5.0 * scale}, duration, o.seed, where);
  };
  write_drive(o, kNightDriveDuration_s, kSpeed_m_s, headlights, gaze);
}

}  // namespace eyestream::samples
