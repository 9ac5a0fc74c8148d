// The per-frame report (`--report FILE.csv`) and its JSON summary
// (FILE.json), both written atomically at the end of the run.
#pragma once

#include <string>

#include "pipeline/eye_simulator.hpp"

namespace eyestream::pipeline {

// Columns, one row per frame:
//   frame, time_s, gaze_x, gaze_y (frame pixels), eye (open|closed),
//   adaptation_cd_m2 (10^A), pupil_mm, peak_cd_m2 (brightest scene pixel),
//   glare (1 when the glare stage ran), veil_cd_m2 (veiling luminance at
//   the gaze from light more than --veil-exclusion away; empty without a
//   Vos PSF or with eyes closed), ti_percent (65 L_v / L_av^0.8, L_av the
//   adaptation luminance; empty with the veil), ti_valid (1 when L_av is
//   within 0.05-5 cd/m^2, the formula's range).
class ReportWriter {
 public:
  ReportWriter(std::string csv_path, double viewer_age_years);
  void add(std::int64_t frame, double time_s, const FrameReport& r);
  // Writes FILE.csv and FILE.json.
  void finish();

 private:
  std::string path_, rows_;
  double age_;
  std::int64_t frames_ = 0, glare_frames_ = 0, closed_frames_ = 0, veil_frames_ = 0;
  double max_veil_ = 0, sum_veil_ = 0, max_ti_ = 0, min_adaptation_ = 1e300, max_adaptation_ = 0;
};

}  // namespace eyestream::pipeline
