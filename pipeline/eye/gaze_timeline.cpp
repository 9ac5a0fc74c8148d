#include "pipeline/eye/gaze_timeline.hpp"

#include <algorithm>
#include <cmath>

namespace eyestream::pipeline {

GazeTimeline::GazeTimeline(const std::vector<io::GazeSample>& samples, double default_x, double default_y) {
  double x = default_x, y = default_y;
  for (const io::GazeSample& s : samples) {
    if (s.state == io::EyeState::kOpen) {
      x = s.x;
      y = s.y;
    }
    held_.push_back({s.t_s, x, y, s.state == io::EyeState::kClosed});
    if (io::has_usable_pupil(s)) pupils_.push_back({s.t_s, s.pupil_mm});
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
  const double pupil = recorded_pupil_mm(t0, t1).value_or(std::numeric_limits<double>::quiet_NaN());
  for (GazeSegment& s : out) s.recorded_pupil_mm = pupil;
  return out;
}

std::optional<double> GazeTimeline::recorded_pupil_mm(double t0, double t1) const {
  if (pupils_.empty()) return std::nullopt;
  auto by_time = [](const Pupil& p, double t) { return p.t_s < t; };
  const auto first = std::lower_bound(pupils_.begin(), pupils_.end(), t0, by_time);
  const auto last = std::lower_bound(first, pupils_.end(), std::max(t1, t0), by_time);
  if (first != last) {
    double sum = 0.0;
    for (auto p = first; p != last; ++p) sum += p->mm;
    return sum / double(last - first);
  }
  // Bridged: between the samples either side, at the interval's middle.
  if (first == pupils_.begin()) return first->mm;
  const Pupil& before = *(first - 1);
  if (first == pupils_.end()) return before.mm;
  const double mid = 0.5 * (t0 + std::max(t1, t0));
  const double w = std::clamp((mid - before.t_s) / (first->t_s - before.t_s), 0.0, 1.0);
  return before.mm + w * (first->mm - before.mm);
}

}  // namespace eyestream::pipeline
