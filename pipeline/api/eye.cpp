#include "eyestream/eye.hpp"

#include "pipeline/api/api_settings.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "pipeline/api/eye_access.hpp"
#include "io/error.hpp"
#include "io/frame_source.hpp"
#include "pipeline/eye/eye_simulator.hpp"
#include "pipeline/eye/gaze_timeline.hpp"
#include "pipeline/eye/target_region.hpp"
#include "pipeline/settings/plan.hpp"
#include "pipeline/settings/settings.hpp"
#include "retina/display_encoding.hpp"

namespace eyestream {

namespace {

// The API's samples as the gaze reader gives them; `what` names them in
// the error.
std::vector<io::GazeSample> gaze_samples(const std::vector<Gaze>& gaze, const std::string& what) {
  std::vector<io::GazeSample> samples;
  for (const Gaze& g : gaze) {
    if (!std::isfinite(g.t_s) || !std::isfinite(g.x) || !std::isfinite(g.y))
      throw UsageError("a gaze sample of " + what + " is not finite");
    // A diameter of 0 or less (how trackers mark a missing pupil) is none.
    const double pupil = std::isfinite(g.pupil_mm) && g.pupil_mm > 0.0 ? g.pupil_mm : NAN;
    samples.push_back({g.t_s, g.x, g.y,
                       g.closed ? io::EyeState::kClosed : g.lost ? io::EyeState::kLost : io::EyeState::kOpen, pupil});
  }
  std::stable_sort(samples.begin(), samples.end(),
                   [](const io::GazeSample& a, const io::GazeSample& b) { return a.t_s < b.t_s; });
  return samples;
}

}  // namespace

struct Eye::Impl {
  pipeline::Plan plan;
  pipeline::EyeSimulator eye;
  pipeline::TargetRegion target;
  int bits = 8;  // of the encoded frame
  std::int64_t index = 0;
  // set_gaze's recording, read as the command line reads a whole log
  // (shared by the panels of a run).
  std::shared_ptr<const pipeline::GazeTimeline> recording;
  // Without one, the gaze carried from earlier frames: the last sample with
  // a position, then the last sample when it is a blink or lost (which
  // hold that position), as the timeline of the whole log has them.
  std::vector<io::GazeSample> carried;
  pipeline::FrameReport last;       // the last frame's
  double last_recorded_pupil = NAN;  // the pupil the last frame's optics took from the gaze, if any

  Impl(pipeline::Plan p, const pipeline::Settings& s)
      : plan(p), eye(std::move(p)), target(s.target_rect, s.target_mask, cv::Size(plan.width, plan.height)),
        bits(s.sink.png_bits) {}

  std::vector<pipeline::GazeSegment> segments(const std::vector<Gaze>& gaze, double t0, double t1) {
    if (recording) {
      if (!gaze.empty())
        throw UsageError("frame " + std::to_string(index) + ": gaze samples given to an eye holding a recording (set_gaze)");
      return recording->segments(t0, t1);
    }
    std::vector<io::GazeSample> samples = carried;
    for (const io::GazeSample& g : gaze_samples(gaze, "frame " + std::to_string(index))) samples.push_back(g);
    std::stable_sort(samples.begin(), samples.end(),
                     [](const io::GazeSample& a, const io::GazeSample& b) { return a.t_s < b.t_s; });
    const pipeline::GazeTimeline timeline(samples, plan.width / 2.0, plan.height / 2.0);
    if (!samples.empty()) {
      const auto known = std::find_if(samples.rbegin(), samples.rend(),
                                      [](const io::GazeSample& g) { return g.state == io::EyeState::kOpen; });
      carried.clear();
      // The last recorded pupil too, when an open sample after it has none
      // (the timeline holds it across frames without one).
      const auto measured = std::find_if(samples.rbegin(), samples.rend(), io::has_usable_pupil);
      if (measured != samples.rend() && measured != known) carried.push_back(*measured);
      if (known != samples.rend()) carried.push_back(*known);
      if (samples.back().state != io::EyeState::kOpen) carried.push_back(samples.back());
    }
    return timeline.segments(t0, t1);
  }

  // The one path through the model, for the API and the command line.
  io::DisplayFrame step(io::SceneFrame scene, const std::vector<pipeline::GazeSegment>& segments) {
    last = pipeline::FrameReport();
    // The target only matters to the report (and its masks are files).
    const cv::Mat mask = plan.report ? target.mask(scene.index) : cv::Mat();
    const std::int64_t next = scene.index + 1;
    io::DisplayFrame shown = eye.process(std::move(scene), segments, &last, mask);
    last_recorded_pupil = plan.pupil_from_gaze ? segments.front().recorded_pupil_mm : NAN;
    index = next;
    return shown;
  }

  FrameReport public_report() const {
    const pipeline::FrameReport& r = last;
    const double model = eye.pupil_mm().value_or(0.0);
    FrameReport out{std::pow(10.0, r.adaptation_log),
                    std::isfinite(last_recorded_pupil) ? last_recorded_pupil : model,
                    model,
                    r.gaze_x,
                    r.gaze_y,
                    r.eye_closed,
                    r.active.glare,
                    r.active.retina,
                    r.active.mesopic,
                    r.active.afterimages};
    if (plan.report) {
      out.peak_cd_m2 = r.peak_cd_m2;
      out.veil_cd_m2 = r.veil_cd_m2;
      out.ti_percent = r.ti_percent;
      out.target_cd_m2 = r.target_cd_m2;
      out.background_cd_m2 = r.background_cd_m2;
      out.target_veil_cd_m2 = r.target_veil_cd_m2;
    }
    out.nonfinite_pixels = r.nonfinite_pixels;
    out.glare_ms = r.times.glare_ms;
    out.adaptation_ms = r.times.adaptation_ms;
    out.retina_ms = r.times.retina_ms;
    out.mesopic_ms = r.times.mesopic_ms;
    out.afterimage_ms = r.times.afterimage_ms;
    return out;
  }
};

Eye::Eye(int width, int height, double fps, const std::map<std::string, std::string>& settings) {
  translated([&] {
    if (width < 1 || height < 1 || !(fps > 0.0))
      throw UsageError("an eye needs a positive size and frame rate, not " + std::to_string(width) + "x" +
                                 std::to_string(height) + " at " + std::to_string(fps) + " fps");
    io::SourceInfo info;
    info.width = width;
    info.height = height;
    info.frames_per_second = fps;
    const pipeline::Settings s = compile_settings(settings);
    impl_ = std::make_unique<Impl>(pipeline::compile_plan(s, info), s);
    return 0;
  });
}

Eye::Eye(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Eye::~Eye() = default;
Eye::Eye(Eye&&) noexcept = default;
Eye& Eye::operator=(Eye&&) noexcept = default;

int Eye::width() const { return impl_->plan.width; }
int Eye::height() const { return impl_->plan.height; }
double Eye::fps() const { return impl_->plan.frames_per_second; }
std::string Eye::describe() const { return impl_->plan.describe(); }

void Eye::set_gaze(const std::vector<Gaze>& recording) {
  translated([&] {
    std::shared_ptr<const pipeline::GazeTimeline> timeline;
    if (!recording.empty())
      timeline = std::make_shared<const pipeline::GazeTimeline>(gaze_samples(recording, "the recording"),
                                                                width() / 2.0, height() / 2.0);
    impl_->carried.clear();
    impl_->recording = std::move(timeline);
    return 0;
  });
}

Frame Eye::process(const cv::Mat& rgb, const std::vector<Gaze>& gaze) {
  return translated([&] {
    if (rgb.type() != CV_32FC3 || rgb.cols != width() || rgb.rows != height())
      throw UsageError("frame " + std::to_string(impl_->index) + " is not a " + std::to_string(width()) +
                                 "x" + std::to_string(height()) + " float RGB image");
    const std::int64_t n = impl_->index;
    const double t0 = double(n) / fps(), t1 = double(n + 1) / fps();
    const io::SceneFrame scene{rgb, t0, n, "frame " + std::to_string(n)};
    Frame out;
    out.linear = impl_->step(scene, impl_->segments(gaze, t0, t1)).linear;
    retina::encode_display(out.linear, impl_->bits, n, impl_->plan.encoding, out.code);
    out.report = impl_->public_report();
    return out;
  });
}

Frame Eye::process(const float* rgb, std::size_t stride_bytes, const std::vector<Gaze>& gaze) {
  if (!rgb || stride_bytes < std::size_t(width()) * 3 * sizeof(float))
    throw Error("frame " + std::to_string(impl_->index) + ": a null pointer or a row stride under " +
                    std::to_string(width() * 3 * sizeof(float)) + " bytes",
                2);
  const cv::Mat view(height(), width(), CV_32FC3, const_cast<float*>(rgb), stride_bytes);
  return process(view, gaze);
}

Eye::State Eye::state() const {
  const pipeline::EyeMemory m = impl_->eye.save();
  State s;
  for (const cv::Mat& mat : m.retina) s.mats.push_back(mat.clone());  // a snapshot: the eye steps its own in place
  s.numbers = {double(impl_->index), m.adaptation_log.value_or(NAN), m.pupil_mm.value_or(NAN),
               m.retina_started ? 1.0 : 0.0};
  for (const io::GazeSample& g : impl_->carried)
    s.numbers.insert(s.numbers.end(), {g.t_s, g.x, g.y, double(int(g.state)), g.pupil_mm});
  return s;
}

void Eye::restore(const State& s) {
  translated([&] {
    const auto whole = [](double v, double most) { return std::isfinite(v) && v >= 0 && v <= most && v == std::floor(v); };
    // Four numbers, then five per carried sample: t, x, y, state, pupil (NaN: none).
    bool ok = s.numbers.size() >= 4 && (s.numbers.size() - 4) % 5 == 0 && whole(s.numbers[0], 1e15);
    for (size_t i = 4; ok && i + 4 < s.numbers.size(); i += 5)
      ok = std::isfinite(s.numbers[i]) && std::isfinite(s.numbers[i + 1]) && std::isfinite(s.numbers[i + 2]) &&
           whole(s.numbers[i + 3], 2) &&
           (std::isnan(s.numbers[i + 4]) || (std::isfinite(s.numbers[i + 4]) && s.numbers[i + 4] > 0.0));
    if (!ok) throw UsageError("the eye's state is malformed");
    pipeline::EyeMemory m;
    m.retina = s.mats;
    if (std::isfinite(s.numbers[1])) m.adaptation_log = s.numbers[1];
    if (std::isfinite(s.numbers[2])) m.pupil_mm = s.numbers[2];
    m.retina_started = s.numbers[3] != 0.0;
    const std::string problem = impl_->eye.memory_error(m);
    if (!problem.empty()) throw UsageError("the eye's state does not fit this eye: " + problem);
    impl_->eye.restore(m);
    impl_->index = std::int64_t(s.numbers[0]);
    impl_->carried.clear();
    for (size_t i = 4; i + 4 < s.numbers.size(); i += 5)
      impl_->carried.push_back(
          {s.numbers[i], s.numbers[i + 1], s.numbers[i + 2], io::EyeState(int(s.numbers[i + 3])), s.numbers[i + 4]});
    return 0;
  });
}

namespace detail {

Eye EyeAccess::make(const pipeline::Settings& settings, const io::SourceInfo& source) {
  return Eye(std::make_unique<Eye::Impl>(pipeline::compile_plan(settings, source), settings));
}

void EyeAccess::set_gaze(Eye& eye, std::shared_ptr<const pipeline::GazeTimeline> recording) {
  eye.impl_->carried.clear();
  eye.impl_->recording = std::move(recording);
}

io::DisplayFrame EyeAccess::process(Eye& eye, io::SceneFrame frame, double t1_s) {
  Eye::Impl& e = *eye.impl_;
  const std::vector<pipeline::GazeSegment> segments =
      e.recording ? e.recording->segments(frame.time_s, t1_s)
                  : pipeline::GazeTimeline({}, e.plan.width / 2.0, e.plan.height / 2.0).segments(frame.time_s, t1_s);
  return e.step(std::move(frame), segments);
}

const pipeline::FrameReport& EyeAccess::report(const Eye& eye) { return eye.impl_->last; }
const pipeline::Plan& EyeAccess::plan(const Eye& eye) { return eye.impl_->plan; }
const pipeline::EyeSimulator& EyeAccess::simulator(const Eye& eye) { return eye.impl_->eye; }
void EyeAccess::restore(Eye& eye, const pipeline::EyeMemory& memory) { eye.impl_->eye.restore(memory); }

}  // namespace detail

}  // namespace eyestream
