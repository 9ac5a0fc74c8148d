#include "samples/dusk.hpp"

#include <cmath>
#include <random>

#include "samples/color_checker.hpp"
#include "samples/scene_writer.hpp"

namespace eyestream::samples {

double dusk_white(double t, double duration, double bright) {
  const double half = duration / 2.0;
  const double f = t < half ? t / half : (duration - t) / half;  // 0 -> 1 -> 0
  return std::pow(10.0, std::log10(bright) + f * (std::log10(kDuskDarkWhite) - std::log10(bright)));
}

cv::Rect dusk_checker_patch(int index, cv::Size frame) {
  const int cell = frame.height / 6, gap = std::max(1, cell / 8);
  const int x0 = frame.width / 20, y0 = frame.height / 6;
  return {x0 + (index % 6) * cell + gap, y0 + (index / 6) * cell + gap, cell - 2 * gap, cell - 2 * gap};
}

cv::Rect dusk_target(cv::Size frame) {
  const int x0 = frame.width / 20 + 6 * (frame.height / 6) + frame.width / 20;
  return {x0, frame.height / 6, frame.width - x0 - frame.width / 20, 4 * (frame.height / 6)};
}

cv::Mat dusk_reflectance(cv::Size frame) {
  cv::Mat r(frame, CV_32FC3, cv::Scalar::all(0.18));  // mid-grey wall
  const auto& patches = color_checker_linear();
  cv::Mat(frame.height / 6 * 4 + 2, frame.height / 6 * 6 + 2, CV_32FC3, cv::Scalar::all(0.03))
      .copyTo(
          r(cv::Rect(frame.width / 20 - 1, frame.height / 6 - 1, frame.height / 6 * 6 + 2, frame.height / 6 * 4 + 2)));
  for (int i = 0; i < 24; ++i) {
    const cv::Vec3f& c = patches[size_t(i)];
    r(dusk_checker_patch(i, frame)).setTo(cv::Scalar(c[0], c[1], c[2]));
  }
  // Resolution target: rows of black-and-white bars, periods 2, 3, 4, 6, 8 and 12 pixels.
  const cv::Rect t = dusk_target(frame);
  const int periods[6] = {2, 3, 4, 6, 8, 12};
  for (int row = 0; row < 6; ++row) {
    const int y0 = t.y + row * t.height / 6, y1 = t.y + (row + 1) * t.height / 6 - 2;
    for (int y = y0; y < y1; ++y)
      for (int x = t.x; x < t.x + t.width; ++x) {
        const bool white = ((x - t.x) % periods[row]) < periods[row] / 2 + (periods[row] % 2 && (y % 2));
        r.at<cv::Vec3f>(y, x) = cv::Vec3f::all(white ? 0.9f : 0.04f);
      }
  }
  return r;
}

void generate_dusk(const SceneOptions& o) {
  const double duration = o.duration_s > 0 ? o.duration_s : kDuskDuration_s;
  const double bright = o.luminance_cd_m2 > 0 ? o.luminance_cd_m2 : kDuskBrightWhite;
  const int frames = std::max(1, int(std::lround(duration * o.fps)));
  const cv::Size size(o.width, o.height);
  const cv::Mat reflectance = dusk_reflectance(size);
  SceneWriter writer(o.out_dir, o.fps, bright / 1000.0);
  for (int i = 0; i < frames; ++i) writer.add_frame(reflectance * dusk_white(i / o.fps, duration, bright));
  // The gaze wanders between the checker and the target: a new point every
  // 0.8 s, reached by a 40 ms saccade, with fixational jitter.
  std::mt19937_64 rng(o.seed ^ 0xd05cULL);
  std::uniform_real_distribution<double> ux(0.08 * o.width, 0.92 * o.width), uy(0.2 * o.height, 0.8 * o.height);
  std::normal_distribution<double> jitter(0.0, 0.5);
  std::vector<io::GazeSample> gaze;
  cv::Point2d from(o.width / 2.0, o.height / 2.0), to = from;
  const double rate = 60.0;
  for (int k = 0; k < int(duration * rate); ++k) {
    const double t = k / rate, phase = std::fmod(t, 0.8);
    if (k > 0 && phase < 1.0 / rate) from = to, to = cv::Point2d(ux(rng), uy(rng));
    const double a = std::min(phase / 0.04, 1.0);
    const cv::Point2d p = from + (to - from) * a;
    gaze.push_back({t, p.x + jitter(rng), p.y + jitter(rng), io::EyeState::kOpen});
  }
  writer.finish(gaze);
}

}  // namespace eyestream::samples
