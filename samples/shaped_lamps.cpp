#include "samples/shaped_lamps.hpp"

#include <cmath>
#include <opencv2/core.hpp>

#include "samples/draw.hpp"
#include "samples/fixed_gaze.hpp"
#include "samples/scene_writer.hpp"

namespace eyestream::samples {

double beacon_luminance(double t_s) {
  const double c = std::cos(2.0 * M_PI * kBeaconTurns_hz * t_s);
  return kBeaconPeak_cd_m2 * (0.01 + (c > 0.0 ? std::pow(c, 8.0) : 0.0));
}

void generate_shaped_lamps(const SceneOptions& o) {
  const double duration = o.duration_s > 0 ? o.duration_s : kShapedLampsDuration_s;
  const double ppd = o.width / 29.3;  // the default viewing condition
  cv::Mat still(o.height, o.width, CV_32FC3, cv::Scalar::all(0.0f));
  paint_rect(still, 0, 0, o.width, 0.55 * o.height, with_luminance({0.6f, 0.7f, 1.0f}, 0.01f));  // night sky
  paint_rect(still, 0, 0.55 * o.height, o.width, o.height, with_luminance({1.0f, 0.9f, 0.8f}, 0.5f));  // street
  // The bar lamp on its arm, left of centre, level.
  const double bx = 0.3 * o.width, by = 0.25 * o.height;
  paint_rect(still, bx - 0.5 * kBarLength_deg * ppd, by - 0.5 * kBarWidth_deg * ppd, bx + 0.5 * kBarLength_deg * ppd,
             by + 0.5 * kBarWidth_deg * ppd, with_luminance({0.95f, 0.97f, 1.0f}, float(kBarLuminance_cd_m2)));
  SceneWriter writer(o.out_dir, o.fps, 100.0);
  const int frames = std::max(1, int(std::lround(duration * o.fps)));
  for (int n = 0; n < frames; ++n) {
    const double t = n / o.fps;
    cv::Mat f = still.clone();
    // The beacon on a parked truck, right of centre (0.1 deg lens).
    add_disc(f, 0.72 * o.width, 0.5 * o.height, 0.1 * ppd,
             with_luminance({1.0f, 0.55f, 0.05f}, float(beacon_luminance(t))));
    // The cyclist's lamp, left to right across the street (0.05 deg).
    const double x = 0.1 * o.width + kCyclistSpeed_deg_s * ppd * t;
    add_disc(f, x, 0.68 * o.height, 0.05 * ppd, cv::Vec3f::all(float(kCyclistLuminance_cd_m2)));
    writer.add_frame(f);
  }
  writer.finish(fixed_gaze(0.5 * o.width, 0.45 * o.height, duration, 120.0));
}

}  // namespace eyestream::samples
