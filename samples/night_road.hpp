// The night road both night drives are rendered on: a pinhole camera
// whose horizontal field of view matches eyestream's default viewing
// geometry (29.3 deg), so geometry and glare sizes agree with the default
// run, street lamps, stars and an oncoming car's headlights.
//
// Luminances (cd/m^2), chosen to be physically plausible:
// - sky 0.003 at the zenith to 0.02 at the horizon, bluish; stars 1-5 (sub-pixel);
// - verge 0.02 x lamp light; asphalt lit by the lamps: L = q E with luminance
//   coefficient q = 0.07 /sr (dry asphalt, CIE R3 class order of magnitude)
//   and E = I cos(theta) / d^2 from 2000 cd lamps 8 m high every 35 m,
//   giving ~2 cd/m^2 under a lamp and ~0.2 between lamps; lane markings 3x;
// - lamp heads: 2000 cd over a 0.3 m-radius disc, ~7000 cd/m^2, sodium orange;
// - the oncoming car's headlights: 1e5 cd/m^2 discs of 9 cm radius (about
//   2500 cd toward the driver each), 1.4 m apart: sub-pixel points far
//   away, drawn by energy (see draw.hpp), then discs over ten pixels wide.
#pragma once

#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "io/gaze_sample.hpp"
#include "samples/scene.hpp"

namespace eyestream::samples {

inline constexpr double kOwnLaneX_m = 1.75;  // camera x; road centre at 0
inline constexpr double kRoadHalfWidth_m = 3.5;
inline constexpr double kLampX_m = 5.0, kLampHeight_m = 8.0, kLampSpacing_m = 35.0, kLampIntensity_cd = 2000.0;
inline constexpr double kHeadlightLuminance = 1e5, kHeadlightRadius_m = 0.09, kHeadlightHeight_m = 0.7;
inline constexpr double kHeadlightHalfSpacing_m = 0.7, kCarLaneX_m = -1.75;

// Projection from world metres (x across, height, z ahead of the eye) to
// frame pixels.
struct RoadCamera {
  double f_px, cx, horizon_v;
  RoadCamera(int width, int height);
  double project_u(double x_w, double z) const;
  double project_v(double height_m, double z) const;
};

// Illuminance (lux) on the road at world (x, z) from the lamps, after the
// car has travelled `travelled_m`.
double lamp_illuminance(double x, double z, double travelled_m);


// The oncoming car's two headlights at distance z.
void render_headlights(cv::Mat& frame, const RoadCamera& cam, double z);
// The point between them.
cv::Point2d headlight_centre(const RoadCamera& cam, double z);

// 40 stars of 1-5 cd/m^2 above the horizon, fixed by `seed`.
class StarField {
 public:
  StarField(const cv::Size& size, const RoadCamera& cam, std::uint64_t seed);
  void render(cv::Mat& frame) const;

 private:
  std::vector<cv::Point2d> at_;
  std::vector<cv::Vec3f> colour_;
};

// Sky, road and verge, the stars, then the street lamps, for the frame
// after the driver has travelled `travelled_m`.
void render_road(cv::Mat& frame, const RoadCamera& cam, double travelled_m, const StarField& stars);

// What a driver looks at; a scene says where each is at time t.
enum class Look { kRoad, kHeadlights, kTarget };
struct Fixation {
  double start_s;
  Look look;
};

// A 120 Hz gaze log with 0.6 px jitter following `fixations` (by start
// time; the first starts at 0), with a 50 ms saccade into each (blending
// from the previous point to the new one, both moving), and the eyes
// closed for `blink_length_s` from each time of `blinks_s`.
std::vector<io::GazeSample> drive_gaze_log(const std::vector<Fixation>& fixations, const std::vector<double>& blinks_s,
                                           double duration_s, std::uint64_t seed,
                                           const std::function<cv::Point2d(Look, double)>& where,
                                           double blink_length_s = 0.15);

// Writes a drive at `speed_m_s` (scene_writer.hpp): each frame is the road,
// then whatever `extras` paints (returning the target mask, or an empty Mat
// for a scene without a target); then the gaze log `gaze` makes.
using DriveExtras = std::function<cv::Mat(cv::Mat& frame, const RoadCamera& cam, double t, double duration_s)>;
using DriveGaze = std::function<std::vector<io::GazeSample>(const RoadCamera& cam, double duration_s)>;
void write_drive(const SceneOptions& o, double default_duration_s, double speed_m_s, const DriveExtras& extras,
                 const DriveGaze& gaze);

}  // namespace eyestream::samples
