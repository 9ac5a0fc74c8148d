// Physical set-up (luminances of the road itself: night_road.hpp):
// - own car at 12 m/s (43 km/h); the oncoming car closes from 450 m to
//   12 m over the drive. Its headlights (about 2500 cd each toward the
//   driver) give an illuminance at the eye of E = 2 I / d^2: 0.025 lx at
//   450 m, 0.5 lx at 100 m, 2 lx at 50 m, 35 lx at 12 m, rising as it nears
//   (the range in which road-lighting practice computes disability glare);
// - a pedestrian 0.5 m x 1.7 m standing on the verge 4.5 m right of the
//   road centre (1 m beyond the edge line), 200 m ahead at the start,
//   passed after about 16 s; mid-grey clothing (diffuse reflectance 0.3)
//   lit by the street lamps and the own low beams (3000 cd toward the verge):
//   L = 0.3 (E_lamps + 3000 / d^2) / pi, about 0.1-3 cd/m^2, against the
//   verge (about a third of the asphalt's luminance) and, above the
//   horizon, the night sky.
#include "samples/night_drive_long.hpp"

#include <algorithm>
#include <cmath>

#include "samples/draw.hpp"
#include "samples/night_road.hpp"

namespace eyestream::samples {

namespace {

constexpr double kSpeed_m_s = 12.0;
constexpr double kCarStartZ_m = 450.0, kCarEndZ_m = 12.0;
constexpr double kPedestrianX_m = 4.5, kPedestrianStartZ_m = 200.0, kPedestrianHalfWidth_m = 0.25;
constexpr double kPedestrianHeight_m = 1.7, kClothingReflectance = 0.3, kOwnBeamIntensity_cd = 3000.0;
constexpr double kNearestDrawn_m = 4.0;

double car_z(double t, double duration) {
  return kCarStartZ_m + (kCarEndZ_m - kCarStartZ_m) * std::clamp(t / duration, 0.0, 1.0);
}

double pedestrian_z(double t) { return kPedestrianStartZ_m - kSpeed_m_s * t; }

double pedestrian_luminance(double z, double travelled_m) {
  const double e = lamp_illuminance(kPedestrianX_m, z, travelled_m) + kOwnBeamIntensity_cd / std::max(z * z, 25.0);
  return kClothingReflectance * e / M_PI;
}

// Paints the pedestrian and returns its mask (empty once passed).
cv::Mat render_pedestrian(cv::Mat& frame, const RoadCamera& cam, double t) {
  const double z = pedestrian_z(t);
  if (z < kNearestDrawn_m) return cv::Mat::zeros(frame.size(), CV_8U);
  const cv::Vec3f clothing = with_luminance(cv::Vec3f(0.9f, 0.95f, 1.0f), float(pedestrian_luminance(z, kSpeed_m_s * t)));
  return paint_rect(frame, cam.project_u(kPedestrianX_m - kPedestrianHalfWidth_m, z),
                    cam.project_v(kPedestrianHeight_m, z), cam.project_u(kPedestrianX_m + kPedestrianHalfWidth_m, z),
                    cam.project_v(0.0, z), clothing);
}

}  // namespace

void generate_night_drive_long(const SceneOptions& o) {
  auto extras = [](cv::Mat& frame, const RoadCamera& cam, double t, double duration) {
    cv::Mat mask = render_pedestrian(frame, cam, t);
    render_headlights(frame, cam, car_z(t, duration));
    return mask;
  };
  // Road 40 m ahead; the pedestrian (while ahead) and the headlights in
  // turn; five blinks. Times scale with --duration.
  auto gaze = [&](const RoadCamera& cam, double duration) {
    const double k = duration / kNightDriveLongDuration_s;
    const cv::Point2d road(cam.project_u(kOwnLaneX_m, 40.0), cam.project_v(0.0, 40.0));
    auto where = [&](Look look, double t) {
      if (look == Look::kHeadlights) return headlight_centre(cam, car_z(t, duration));
      const double z = pedestrian_z(t);
      if (look == Look::kTarget && z > kNearestDrawn_m)
        return cv::Point2d(cam.project_u(kPedestrianX_m, z), cam.project_v(kPedestrianHeight_m / 2, z));
      return road;
    };
    const std::vector<Fixation> fixations = {
        {0.0, Look::kRoad},           {2.0 * k, Look::kTarget},      {3.2 * k, Look::kRoad},
        {5.5 * k, Look::kHeadlights}, {6.8 * k, Look::kRoad},        {9.0 * k, Look::kTarget},
        {10.5 * k, Look::kRoad},      {12.5 * k, Look::kHeadlights}, {13.8 * k, Look::kTarget},
        {15.0 * k, Look::kRoad},      {17.0 * k, Look::kHeadlights}, {17.8 * k, Look::kRoad}};
    return drive_gaze_log(fixations, {4.5 * k, 8.2 * k, 11.6 * k, 16.2 * k, 19.0 * k}, duration, o.seed, where);
  };
  write_drive(o, kNightDriveLongDuration_s, kSpeed_m_s, extras, gaze);
}

}  // namespace eyestream::samples
