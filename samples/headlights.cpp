#include "samples/headlights.hpp"

#include <cmath>

#include "samples/draw.hpp"
#include "samples/fixed_gaze.hpp"
#include "samples/scene_writer.hpp"

namespace eyestream::samples {

namespace {
double default_ppd(int width) { return width / 29.3; }  // the default viewing condition
}  // namespace

cv::Rect headlights_target(cv::Size frame) {
  const double ppd = default_ppd(frame.width);
  const int w = std::max(1, int(std::lround(0.3 * ppd))), h = std::max(1, int(std::lround(1.0 * ppd)));
  const int cx = int(std::lround(frame.width / 2.0 - kHeadlightsTargetOffset_deg * ppd));
  return {cx - w / 2, frame.height / 2 - h / 2, w, h};
}

void generate_headlights(const SceneOptions& o) {
  const double duration = o.duration_s > 0 ? o.duration_s : kHeadlightsDuration_s;
  const double lamp = o.luminance_cd_m2 > 0 ? o.luminance_cd_m2 : kHeadlightsLuminance;
  const double ppd = default_ppd(o.width);
  cv::Mat frame(o.height, o.width, CV_32FC3, cv::Scalar::all(kHeadlightsRoad));
  frame(headlights_target(frame.size())).setTo(cv::Scalar::all(kHeadlightsTarget));
  for (double side : {-0.5, 0.5})
    add_disc(frame, o.width / 2.0 + side * kHeadlightsSpacing_deg * ppd, o.height / 2.0, kHeadlightsRadius_deg * ppd,
             cv::Vec3f::all(float(lamp)));
  SceneWriter writer(o.out_dir, o.fps, lamp / 1000.0);
  const int frames = std::max(1, int(std::lround(duration * o.fps)));
  const cv::Rect t = headlights_target(frame.size());
  cv::Mat mask = cv::Mat::zeros(frame.size(), CV_8U);
  mask(t).setTo(255);
  for (int i = 0; i < frames; ++i) writer.add_frame(frame, mask);
  writer.finish(fixed_gaze(t.x + t.width / 2.0, t.y + t.height / 2.0, duration, 60.0));
}

}  // namespace eyestream::samples
