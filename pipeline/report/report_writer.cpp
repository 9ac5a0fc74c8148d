#include "pipeline/report/report_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "glare/veiling_luminance.hpp"
#include "io/error.hpp"
#include "io/staged_file.hpp"
#include "pipeline/report/report_charts.hpp"
#include "pipeline/eye/target_region.hpp"

namespace eyestream::pipeline {

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.6g", v);
  return buf;
}

// A value, or an empty field when it is unknown.
std::string field(bool known, double v) { return known ? number(v) : ""; }

io::StagedFile stage_text(const std::string& path, const std::string& text) {
  io::StagedFile file(path);
  io::write_all(file, std::vector<unsigned char>(text.begin(), text.end()));
  return file;
}

}  // namespace

ReportWriter::ReportWriter(std::string csv_path, std::vector<ReportViewer> viewers)
    : path_(std::move(csv_path)), viewers_(std::move(viewers)), summary_(viewers_.size()) {
  for (ReportViewer& v : viewers_) std::replace(v.label.begin(), v.label.end(), ',', ';');  // one CSV field
  rows_ = std::string(kReportColumns) + "\n";
}

void ReportWriter::add(std::int64_t frame, double time_s, size_t viewer, const FrameReport& r) {
  const double adaptation = std::pow(10.0, r.adaptation_log);
  const bool veil = r.veil_cd_m2 >= 0.0, target = r.target_cd_m2 >= 0.0;
  const bool target_veil = target && r.target_veil_cd_m2 >= 0.0;
  const double contrast = target ? luminance_contrast(r.target_cd_m2, r.background_cd_m2) : 0.0;
  const double veiled = target_veil ? luminance_contrast(r.target_cd_m2, r.background_cd_m2, r.target_veil_cd_m2) : 0.0;
  rows_ += std::to_string(frame) + "," + number(time_s) + "," + viewers_[viewer].label + "," + number(r.gaze_x) + "," +
           number(r.gaze_y) + "," + (r.eye_closed ? "closed" : "open") + "," + number(adaptation) + "," +
           number(r.pupil_mm) + "," + number(r.peak_cd_m2) + "," + (r.active.glare || r.active.glare_reused ? "1" : "0") + "," +
           field(veil, r.veil_cd_m2) + "," + field(veil, r.ti_percent) + "," +
           (glare::threshold_increment_valid(adaptation) ? "1" : "0") + "," + field(target, r.target_cd_m2) + "," +
           field(target, r.background_cd_m2) + "," + field(target_veil, r.target_veil_cd_m2) + "," +
           field(target, contrast) + "," + field(target_veil, veiled) + "," + (r.active.retina ? "1" : "0") + "," +
           (r.active.afterimages ? "1" : "0") + "," + (r.active.mesopic ? "1" : "0") + "," +
           (r.active.acuity ? "1" : "0") + "," + number(r.pupil_model_mm) + "," +
           field(r.pupil_recorded_mm > 0.0, r.pupil_recorded_mm) + "\n";
  Summary& s = summary_[viewer];
  ++s.frames;
  s.glare_frames += r.active.glare || r.active.glare_reused;
  s.closed_frames += r.eye_closed;
  s.min_adaptation = std::min(s.min_adaptation, adaptation);
  s.max_adaptation = std::max(s.max_adaptation, adaptation);
  if (veil) {
    ++s.veil_frames;
    s.sum_veil += r.veil_cd_m2;
    s.max_veil = std::max(s.max_veil, r.veil_cd_m2);
    s.max_ti = std::max(s.max_ti, r.ti_percent);
  }
  if (target) {
    ++s.target_frames;
    s.min_contrast = std::min(s.min_contrast, std::abs(contrast));
    if (target_veil) s.min_contrast_veiled = std::min(s.min_contrast_veiled, std::abs(veiled));
  }
}

std::vector<io::StagedFile> ReportWriter::stage() const {
  nlohmann::json viewers = nlohmann::json::array();
  for (size_t i = 0; i < viewers_.size(); ++i) {
    const Summary& s = summary_[i];
    nlohmann::json v = {{"label", viewers_[i].label},
                        {"viewer_age_years", viewers_[i].age_years},
                        {"frames", s.frames},
                        {"frames_with_glare", s.glare_frames},
                        {"frames_with_eyes_closed", s.closed_frames},
                        {"adaptation_cd_m2", {{"min", s.min_adaptation}, {"max", s.max_adaptation}}},
                        {"veil_cd_m2", {{"max", s.max_veil}, {"mean", s.veil_frames ? s.sum_veil / s.veil_frames : 0.0}}},
                        {"ti_percent_max", s.max_ti},
                        {"frames_with_target", s.target_frames}};
    if (s.target_frames) {
      v["target_abs_contrast_min"] = s.min_contrast;
      if (s.min_contrast_veiled < 1e300) v["target_abs_contrast_veiled_min"] = s.min_contrast_veiled;
    }
    viewers.push_back(v);
  }
  const std::int64_t frames = summary_.empty() ? 0 : summary_[0].frames;
  nlohmann::json summary = {{"eyestream", EYESTREAM_VERSION}, {"frames", frames}, {"viewers", viewers}};
  if (!gaze_.is_null()) summary["gaze"] = gaze_;
  std::vector<io::StagedFile> files;
  files.push_back(stage_text(path_, rows_));
  files.push_back(stage_text(std::filesystem::path(path_).replace_extension(".json").string(), summary.dump(2) + "\n"));
  files.push_back(
      stage_report_charts(parse_report(rows_, path_), std::filesystem::path(path_).replace_extension(".png").string()));
  return files;
}

void ReportWriter::set_gaze(const io::GazeSummary& g) {
  gaze_ = {{"format", g.format},         {"samples", g.samples},         {"median_interval_s", g.median_interval_s},
           {"first_s", g.first_s},       {"last_s", g.last_s},           {"lost_share", g.lost_share},
           {"closed_share", g.closed_share}, {"off_frame_share", g.off_frame_share}, {"warnings", g.warnings},
           {"notes", g.notes}};
}

nlohmann::json ReportWriter::save() const {
  nlohmann::json summaries = nlohmann::json::array();
  for (const Summary& m : summary_)
    summaries.push_back({m.frames, m.glare_frames, m.closed_frames, m.veil_frames, m.target_frames, m.max_veil,
                         m.sum_veil, m.max_ti, m.min_adaptation, m.max_adaptation, m.min_contrast,
                         m.min_contrast_veiled});
  return {{"rows", rows_}, {"summaries", summaries}};
}

void ReportWriter::restore(const nlohmann::json& saved) {
  rows_ = saved.at("rows").get<std::string>();
  const nlohmann::json& all = saved.at("summaries");
  if (all.size() != summary_.size()) throw InputError("checkpoint: the report has another number of viewers");
  for (size_t i = 0; i < summary_.size(); ++i) {
    const nlohmann::json& v = all[i];
    Summary& m = summary_[i];
    m.frames = v[0], m.glare_frames = v[1], m.closed_frames = v[2], m.veil_frames = v[3], m.target_frames = v[4];
    m.max_veil = v[5], m.sum_veil = v[6], m.max_ti = v[7], m.min_adaptation = v[8], m.max_adaptation = v[9];
    m.min_contrast = v[10], m.min_contrast_veiled = v[11];
  }
}

}  // namespace eyestream::pipeline
