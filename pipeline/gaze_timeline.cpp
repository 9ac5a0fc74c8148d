#include "pipeline/gaze_timeline.hpp"

#include <algorithm>

namespace eyestream::pipeline {

GazeTimeline::GazeTimeline(const std::vector<io::GazeSample>& samples, double default_x, double default_y) {
  double x = default_x, y = default_y;
  for (const io::GazeSample& s : samples) {
    if (s.state == io::EyeState::kOpen) {
      x = s.x;
      y = s.y;
    }
    held_.push_back({s.t_s, x, y, s.state == io::EyeState::kClosed});
  }
  if (held_.empty()) held_.push_back({0.0, default_x, default_y, false});
}

std::vector<GazeSegment> GazeTimeline::segments(double t0, double t1) const {
  auto by_time = [](double t, const Held& h) { return t < h.t_s; };
  // The sample in force at t0: the last one at or before it, else the first.
  auto it = std::upper_bound(held_.begin(), held_.end(), t0, by_time);
  size_t k = it == held_.begin() ? 0 : size_t(it - held_.begin()) - 1;
  std::vector<GazeSegment> out;
  double t = t0;
  for (;;) {
    const double next = k + 1 < held_.size() ? held_[k + 1].t_s : t1;
    const double end = std::min(next, t1);
    if (end > t || out.empty()) out.push_back({t, std::max(end, t), held_[k].x, held_[k].y, held_[k].closed});
    if (end >= t1) break;
    t = end;
    ++k;
  }
  return out;
}

}  // namespace eyestream::pipeline
