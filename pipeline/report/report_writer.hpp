// The per-frame report (`--report FILE.csv`), its JSON summary (FILE.json)
// and its charts (FILE.png, report_charts.hpp), written atomically at the
// end of the run.
#pragma once

#include "io/gaze_summary.hpp"

#include "io/staged_file.hpp"
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pipeline/eye/eye_simulator.hpp"

namespace eyestream::pipeline {

// Columns, one row per frame and viewer (frames x viewers rows):
//   frame, time_s, viewer (its label), gaze_x, gaze_y (frame pixels),
//   eye (open|closed), adaptation_cd_m2 (10^A), pupil_mm, peak_cd_m2
//   (brightest scene pixel), glare (1 when the glare stage ran),
//   veil_cd_m2 (veiling luminance at the gaze from light more than
//   --veil-exclusion away; empty without a Vos PSF or with eyes closed),
//   ti_percent (65 L_v / L_av^0.8, L_av the adaptation luminance; empty
//   with the veil), ti_valid (1 when L_av is within 0.05-5 cd/m^2, the
//   formula's range), and with a target (--target or --target-mask; empty
//   in frames without one): target_cd_m2, background_cd_m2 (its surround),
//   target_veil_cd_m2 (veil at the target's centroid), contrast
//   ((L_t - L_b) / L_b) and contrast_veiled ((L_t - L_b) / (L_b + L_v),
//   empty when the veil is); retina, afterimages, mesopic, acuity (1 when
//   the stage worked); pupil_model_mm (the pupil model's diameter) and
//   pupil_recorded_mm (the gaze log's for the frame, bridged across blinks;
//   empty without one): pupil_mm is the recorded one with --pupil-from-gaze.
inline constexpr const char* kReportColumns =
    "frame,time_s,viewer,gaze_x,gaze_y,eye,adaptation_cd_m2,pupil_mm,peak_cd_m2,glare,veil_cd_m2,ti_percent,"
    "ti_valid,target_cd_m2,background_cd_m2,target_veil_cd_m2,contrast,contrast_veiled,retina,afterimages,mesopic,"
    "acuity,pupil_model_mm,pupil_recorded_mm";

struct ReportViewer {
  std::string label;
  double age_years = 0.0;
};

class ReportWriter {
 public:
  ReportWriter(std::string csv_path, std::vector<ReportViewer> viewers);
  void add(std::int64_t frame, double time_s, size_t viewer, const FrameReport& r);
  // What the gaze log held (gaze_summary.hpp), for the JSON summary.
  void set_gaze(const io::GazeSummary& gaze);
  // Writes FILE.csv, FILE.json and FILE.png under temporary names, for the
  // caller to commit with the run's other outputs.
  std::vector<io::StagedFile> stage() const;
  // Checkpoints: the rows and summaries so far, and back.
  nlohmann::json save() const;
  void restore(const nlohmann::json& saved);

 private:
  struct Summary {
    std::int64_t frames = 0, glare_frames = 0, closed_frames = 0, veil_frames = 0, target_frames = 0;
    double max_veil = 0, sum_veil = 0, max_ti = 0, min_adaptation = 1e300, max_adaptation = 0;
    double min_contrast = 1e300, min_contrast_veiled = 1e300;
  };
  std::string path_, rows_;
  std::vector<ReportViewer> viewers_;
  std::vector<Summary> summary_;
  nlohmann::json gaze_;
};

}  // namespace eyestream::pipeline
