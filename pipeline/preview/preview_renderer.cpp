#include "pipeline/preview/preview_renderer.hpp"

#include "pipeline/preview/hdr10_encoding.hpp"
#include "retina/display_encoding.hpp"

namespace eyestream::pipeline {

PreviewRenderer::PreviewRenderer(const Settings& s, const io::SourceInfo& source, io::SinkNeeds needs)
    : needs_(needs) {
  for (PanelSpec& spec : panel_specs(s)) {
    Plan plan = compile_plan(spec.settings, source);
    plan.report = plan.report && spec.viewer;
    auto eye = std::make_unique<EyeSimulator>(plan);
    panels_.push_back({std::move(spec), std::move(plan), std::move(eye), FrameReport()});
  }
  options_.labels = s.labels;
  options_.gaze = s.gaze_overlay;
  options_.timecode = s.timecode;
  options_.marker_radius_px = panels_[0].plan.pixels_per_degree;  // 1 deg: around, not over, the fixated object
}

io::DisplayFrame PreviewRenderer::process(const io::SceneFrame& frame, const std::vector<GazeSegment>& segments,
                                          const cv::Mat& target_mask) {
  std::vector<PanelView> views;
  for (Panel& p : panels_) {
    p.report = FrameReport();
    io::DisplayFrame seen = p.eye->process(frame, segments, &p.report, target_mask);
    views.push_back({seen.linear, p.spec.label, p.report.gaze_x, p.report.gaze_y, p.report.eye_closed});
  }
  io::DisplayFrame out;
  out.index = frame.index;
  out.time_s = frame.time_s;
  out.linear = compose_preview(views, options_, frame.time_s, frame.index);
  if (needs_ == io::SinkNeeds::kPq16)
    encode_hdr10(out.linear, panels_[0].plan.glare.display_peak_cd_m2, out.code);
  else if (needs_ != io::SinkNeeds::kLinear)
    retina::encode_display(out.linear, needs_ == io::SinkNeeds::kCode16 ? 16 : 8, frame.index,
                           panels_[0].plan.encoding, out.code);
  return out;
}

std::vector<EyeMemory> PreviewRenderer::save() const {
  std::vector<EyeMemory> out;
  for (const Panel& p : panels_) out.push_back(p.eye->save());
  return out;
}

void PreviewRenderer::restore(const std::vector<EyeMemory>& memories) {
  CV_Assert(memories.size() == panels_.size());
  for (size_t i = 0; i < panels_.size(); ++i) panels_[i].eye->restore(memories[i]);
}

std::string PreviewRenderer::memory_error(const std::vector<EyeMemory>& memories) const {
  if (memories.size() != panels_.size()) return "panels";
  for (size_t i = 0; i < panels_.size(); ++i) {
    const std::string e = panels_[i].eye->memory_error(memories[i]);
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
  if (panels_.size() == 1) return panels_[0].plan.describe();
  std::string text;
  for (const Panel& p : panels_) text += "[panel: " + p.spec.label + "]\n" + p.plan.describe();
  return text;
}

}  // namespace eyestream::pipeline
