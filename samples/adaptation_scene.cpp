#include "samples/adaptation_scene.hpp"

#include <cmath>

#include "samples/draw.hpp"
#include "samples/fixed_gaze.hpp"
#include "samples/scene_writer.hpp"

namespace eyestream::samples {

void generate_adaptation(const SceneOptions& o) {
  const double duration = o.duration_s > 0 ? o.duration_s : kAdaptationDuration_s;
  const double switch_s = duration * kAdaptationSwitch_s / kAdaptationDuration_s;
  const int frames = std::max(1, int(std::lround(duration * o.fps)));
  const cv::Vec3f grey = cv::Vec3f::all(float(kAdaptationGrey));
  const cv::Vec3f white = cv::Vec3f::all(float(o.luminance_cd_m2 > 0 ? o.luminance_cd_m2 : kAdaptationWhite));
  const cv::Vec3f blue = with_luminance(cv::Vec3f(0.0f, 0.0f, 1.0f), float(kAdaptationGrey));  // Rec.709 blue primary
  const int half = int(std::lround(kPatchHalf * o.height));
  auto patch = [&](double cx) {
    return cv::Rect(int(std::lround(cx * o.width)) - half, int(std::lround(kPatchY * o.height)) - half, 2 * half,
                    2 * half);
  };
  cv::Mat before(o.height, o.width, CV_32FC3, cv::Scalar(grey[0], grey[1], grey[2]));
  before(patch(kWhitePatchX)).setTo(cv::Scalar(white[0], white[1], white[2]));
  before(patch(kBluePatchX)).setTo(cv::Scalar(blue[0], blue[1], blue[2]));
  const cv::Mat after(o.height, o.width, CV_32FC3, cv::Scalar(grey[0], grey[1], grey[2]));
  SceneWriter writer(o.out_dir, o.fps, 1.0);
  for (int i = 0; i < frames; ++i) writer.add_frame(i / o.fps < switch_s - 1e-9 ? before : after);
  writer.finish(fixed_gaze(o.width / 2.0, kPatchY * o.height, duration, 60.0));
}

}  // namespace eyestream::samples
