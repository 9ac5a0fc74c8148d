#include "pipeline/preview/preview_renderer.hpp"

#include "pipeline/preview/hdr10_encoding.hpp"
#include "retina/display_encoding.hpp"

namespace eyestream::pipeline {

PreviewRenderer::PreviewRenderer(const Settings& s, const io::SourceInfo& source, io::SinkNeeds needs)
    : needs_(needs) {
  for (PanelSpec& spec : panel_specs(s)) {
    if (!spec.viewer) spec.settings.report.clear();  // a reference panel has no report
    Eye eye = detail::EyeAccess::make(spec.settings, source);
    panels_.push_back({std::move(spec), std::move(eye)});
  }
  options_.labels = s.labels;
  options_.gaze = s.gaze_overlay;
  options_.timecode = s.timecode;
  options_.marker_radius_px = plan(0).pixels_per_degree;  // 1 deg: around, not over, the fixated object
}

void PreviewRenderer::set_gaze(const std::vector<io::GazeSample>& recording) {
  const auto timeline = std::make_shared<const GazeTimeline>(recording, plan(0).width / 2.0, plan(0).height / 2.0);
  for (Panel& p : panels_) detail::EyeAccess::set_gaze(p.eye, timeline);
}

io::DisplayFrame PreviewRenderer::process(io::SceneFrame frame, double t1_s) {
  std::vector<PanelView> views;
  io::DisplayFrame out;
  out.index = frame.index;
  out.time_s = frame.time_s;
  for (Panel& p : panels_) {
    io::DisplayFrame seen =
        detail::EyeAccess::process(p.eye, &p == &panels_.back() ? std::move(frame) : frame, t1_s);
    const FrameReport& r = detail::EyeAccess::report(p.eye);
    views.push_back({seen.linear, p.spec.label, r.gaze_x, r.gaze_y, r.eye_closed});
  }
  out.linear = compose_preview(views, options_, out.time_s, out.index);
  if (needs_ == io::SinkNeeds::kPq16)
    encode_hdr10(out.linear, plan(0).glare.display_peak_cd_m2, out.code);
  else if (needs_ != io::SinkNeeds::kLinear)
    retina::encode_display(out.linear, needs_ == io::SinkNeeds::kCode16 ? 16 : 8, out.index,
                           plan(0).encoding, out.code);
  // A sink of codes reads only them: the float frame is not sent on, so a
  // frame waiting for the writer holds 6 MB at 1080p, not 31, while the
  // next frame's glare runs.
  if (needs_ != io::SinkNeeds::kLinear) out.linear.release();
  return out;
}

std::vector<EyeMemory> PreviewRenderer::save() const {
  std::vector<EyeMemory> out;
  for (size_t i = 0; i < panels_.size(); ++i) out.push_back(eye(i).save());
  return out;
}

void PreviewRenderer::restore(const std::vector<EyeMemory>& memories) {
  CV_Assert(memories.size() == panels_.size());
  for (size_t i = 0; i < panels_.size(); ++i) detail::EyeAccess::restore(panels_[i].eye, memories[i]);
}

std::string PreviewRenderer::memory_error(const std::vector<EyeMemory>& memories) const {
  if (memories.size() != panels_.size()) return "panels";
  for (size_t i = 0; i < panels_.size(); ++i) {
    const std::string e = eye(i).memory_error(memories[i]);
    if (!e.empty()) return "panel " + std::to_string(i + 1) + ": " + e;
  }
  return "";
}

size_t PreviewRenderer::main_panel() const {
  for (size_t i = 0; i < panels_.size(); ++i)
    if (panels_[i].spec.viewer) return i;
  return 0;
}

std::string PreviewRenderer::describe() const {
  if (panels_.size() == 1) return panels_[0].eye.describe();
  std::string text;
  for (const Panel& p : panels_) text += "[panel: " + p.spec.label + "]\n" + p.eye.describe();
  return text;
}

}  // namespace eyestream::pipeline
