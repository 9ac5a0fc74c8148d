// Charts of a run's report (`eyestream report FILE.csv`, and FILE.png
// beside every --report): adaptation luminance, pupil, veiling luminance,
// TI and, with a target, its contrast over time, one line per viewer, with
// blinks shaded and the frames where the glare stage ran marked.
#pragma once

#include "io/staged_file.hpp"
#include <string>
#include <vector>

namespace eyestream::pipeline {

// One viewer's rows; NaN where a field is empty.
struct ReportSeries {
  std::string label;
  std::vector<double> time_s, adaptation_cd_m2, pupil_mm, veil_cd_m2, ti_percent, contrast, contrast_veiled;
  std::vector<bool> eye_closed, glare_ran;
};

// Parses report CSV text (report_writer.hpp's columns); InputError naming
// `origin` and the line for a missing column or a malformed number.
std::vector<ReportSeries> parse_report(const std::string& csv_text, const std::string& origin);

// Reads a report CSV and draws its charts (`eyestream report`); the PNG
// must not be the CSV. InputError or OutputError naming the file.
void draw_report_file(const std::string& csv_path, const std::string& png_path);

// Draws the charts to a PNG (staged, then renamed).
void write_report_charts(const std::vector<ReportSeries>& series, const std::string& png_path);
// The same, left under its temporary name for the caller to commit.
io::StagedFile stage_report_charts(const std::vector<ReportSeries>& series, const std::string& png_path);

}  // namespace eyestream::pipeline
