#include "pipeline/report_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "glare/veiling_luminance.hpp"
#include "io/staged_file.hpp"

namespace eyestream::pipeline {

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.6g", v);
  return buf;
}

void write_text(const std::string& path, const std::string& text) {
  io::StagedFile file(path);
  io::write_all(file, std::vector<unsigned char>(text.begin(), text.end()));
  file.commit();
}

}  // namespace

ReportWriter::ReportWriter(std::string csv_path, double viewer_age_years)
    : path_(std::move(csv_path)), age_(viewer_age_years) {
  rows_ = "frame,time_s,gaze_x,gaze_y,eye,adaptation_cd_m2,pupil_mm,peak_cd_m2,glare,veil_cd_m2,ti_percent,ti_valid\n";
}

void ReportWriter::add(std::int64_t frame, double time_s, const FrameReport& r) {
  const double adaptation = std::pow(10.0, r.adaptation_log);
  const bool veil = r.veil_cd_m2 >= 0.0;
  rows_ += std::to_string(frame) + "," + number(time_s) + "," + number(r.gaze_x) + "," + number(r.gaze_y) + "," +
           (r.eye_closed ? "closed" : "open") + "," + number(adaptation) + "," + number(r.pupil_mm) + "," +
           number(r.peak_cd_m2) + "," + (r.glare_ran ? "1" : "0") + "," + (veil ? number(r.veil_cd_m2) : "") + "," +
           (veil ? number(r.ti_percent) : "") + "," + (glare::threshold_increment_valid(adaptation) ? "1" : "0") + "\n";
  ++frames_;
  glare_frames_ += r.glare_ran;
  closed_frames_ += r.eye_closed;
  min_adaptation_ = std::min(min_adaptation_, adaptation);
  max_adaptation_ = std::max(max_adaptation_, adaptation);
  if (veil) {
    ++veil_frames_;
    sum_veil_ += r.veil_cd_m2;
    max_veil_ = std::max(max_veil_, r.veil_cd_m2);
    max_ti_ = std::max(max_ti_, r.ti_percent);
  }
}

void ReportWriter::finish() {
  nlohmann::json summary = {
      {"frames", frames_},
      {"viewer_age_years", age_},
      {"frames_with_glare", glare_frames_},
      {"frames_with_eyes_closed", closed_frames_},
      {"adaptation_cd_m2", {{"min", min_adaptation_}, {"max", max_adaptation_}}},
      {"veil_cd_m2", {{"max", max_veil_}, {"mean", veil_frames_ ? sum_veil_ / veil_frames_ : 0.0}}},
      {"ti_percent_max", max_ti_}};
  write_text(path_, rows_);
  write_text(std::filesystem::path(path_).replace_extension(".json").string(), summary.dump(2) + "\n");
}

}  // namespace eyestream::pipeline
