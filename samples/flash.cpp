#include "samples/flash.hpp"

#include <cmath>

#include "samples/draw.hpp"
#include "samples/fixed_gaze.hpp"
#include "samples/scene_writer.hpp"

namespace eyestream::samples {

namespace {
constexpr double kDefaultPixelsPerDegree = 640.0 / 29.3;  // default viewing condition at 640 px
}

void generate_flash(const SceneOptions& o) {
  const double duration = o.duration_s > 0 ? o.duration_s : kFlashDuration_s;
  const double luminance = o.luminance_cd_m2 > 0 ? o.luminance_cd_m2 : kFlashLuminance;
  const int frames = std::max(1, int(std::lround(duration * o.fps)));
  const double radius = kFlashRadius_deg * kDefaultPixelsPerDegree * o.width / 640.0;
  // Frames are stored as L / white with white = luminance / 1000, so any
  // flash fits half floats (largest 65504).
  SceneWriter writer(o.out_dir, o.fps, luminance / 1000.0);
  for (int i = 0; i < frames; ++i) {
    const double t = i / o.fps;
    cv::Mat frame = cv::Mat::zeros(o.height, o.width, CV_32FC3);
    // A frame shows the flash when its start time falls in the flash: 1/8 s
    // exactly at 24, 32 or 40 fps; at 30 fps 4 frames (0.133 s).
    if (t >= kFlashStart_s - 1e-9 && t < kFlashStart_s + kFlashLength_s - 1e-9)
      add_disc(frame, o.width / 2.0, o.height / 2.0, radius, cv::Vec3f::all(float(luminance)));
    writer.add_frame(frame);
  }
  writer.finish(fixed_gaze(o.width / 2.0, o.height / 2.0, duration, 60.0));
}

}  // namespace eyestream::samples
