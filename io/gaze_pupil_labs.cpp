// Pupil Labs exports: Pupil Core / Pupil Player gaze_positions.csv and
// Pupil Labs Neon gaze.csv.
#include <cmath>

#include "io/delimited_table.hpp"
#include "io/error.hpp"
#include "io/gaze_import.hpp"

namespace eyestream::io {

namespace {

int require(const DelimitedTable& t, const std::string& column, const std::string& name) {
  const int c = t.column(column);
  if (c < 0) throw InputError(name + ":" + std::to_string(t.header_line) + ": no column '" + column + "'");
  return c;
}

const std::string& field(const std::vector<std::string>& row, int c, const std::string& where) {
  if (c >= int(row.size())) throw InputError(where + ": too few fields");
  return row[size_t(c)];
}

}  // namespace

// Pupil Core: gaze_timestamp (older Pupil Player: timestamp) in s of the
// Pupil clock, confidence, norm_pos_x/y in 0..1 of the world camera with
// the origin at the bottom left.
std::vector<GazeSample> parse_pupil_core(const std::string& text, const std::string& name, const GazeImportOptions& o,
                                         GazeNotes& notes) {
  const DelimitedTable t = parse_delimited(text, ',');
  const int ct = t.column("gaze_timestamp") >= 0 ? t.column("gaze_timestamp") : require(t, "timestamp", name);
  if (t.column("gaze_timestamp") < 0) notes.push_back("an older Pupil Player export (timestamp, not gaze_timestamp)");
  const int cc = require(t, "confidence", name);
  const int cx = require(t, "norm_pos_x", name), cy = require(t, "norm_pos_y", name);
  const std::string time_name = t.header[size_t(ct)];
  std::vector<GazeSample> out;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::string where = name + ":" + std::to_string(t.line_numbers[r]);
    GazeSample s;
    double confidence, nx, ny;
    if (!parse_number(field(t.rows[r], ct, where), s.t_s)) throw InputError(where + ": " + time_name + " is not a number");
    if (!parse_number(field(t.rows[r], cc, where), confidence))
      throw InputError(where + ": confidence is not a number");
    const bool position =
        parse_number(field(t.rows[r], cx, where), nx) && parse_number(field(t.rows[r], cy, where), ny);
    place(s, confidence >= o.min_confidence && position, nx, 1.0 - ny, o.frame_width, o.frame_height);
    out.push_back(s);
  }
  return out;
}

namespace {

// A Neon boolean: true/True/1/1.0 or false/False/0/0.0 (numbers: non-zero is true).
bool neon_true(const std::string& v) {
  double number;
  if (parse_number(v, number)) return number != 0.0;
  return !(v == "false" || v == "False" || v == "FALSE");
}

bool has(const std::vector<std::string>& row, int c) { return c >= 0 && c < int(row.size()) && !row[size_t(c)].empty(); }

// The rows of a Neon table: timestamp [ns] (UTC); the position (x sx,
// y sy) when it is there and the glasses are worn (column cw; -1: always);
// closed during a blink (a non-empty blink id).
std::vector<GazeSample> neon_rows(const DelimitedTable& t, const std::string& name, int ct, int cx, int cy, int cw,
                                  double sx, double sy) {
  const int cb = t.column("blink id");
  std::vector<GazeSample> out;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::vector<std::string>& row = t.rows[r];
    const std::string where = name + ":" + std::to_string(t.line_numbers[r]);
    GazeSample s;
    double ns, x, y;
    if (!parse_number(field(row, ct, where), ns)) throw InputError(where + ": timestamp [ns] is not a number");
    s.t_s = ns * 1e-9;
    const bool position = parse_number(field(row, cx, where), x) && parse_number(field(row, cy, where), y);
    if (has(row, cb))
      s.state = EyeState::kClosed;
    else
      place(s, (!has(row, cw) || neon_true(row[size_t(cw)])) && position, x, y, sx, sy);
    out.push_back(s);
  }
  return out;
}

}  // namespace

// Neon: gaze x/y [px] in the 1600x1200 scene camera, worn (0/1, 0.0/1.0 or
// true/false).
std::vector<GazeSample> parse_neon(const std::string& text, const std::string& name, const GazeImportOptions& o,
                                   GazeNotes& notes) {
  DelimitedTable t = parse_delimited(text, ',');
  keep_recording(t, t.column("recording id"), o.recording, name, notes);
  const int ct = require(t, "timestamp [ns]", name), cx = require(t, "gaze x [px]", name),
            cy = require(t, "gaze y [px]", name);
  const double sx = double(o.frame_width) / (o.source_width > 0 ? o.source_width : 1600);
  const double sy = double(o.frame_height) / (o.source_height > 0 ? o.source_height : 1200);
  return neon_rows(t, name, ct, cx, cy, t.column("worn"), sx, sy);
}

// Neon Marker Mapper (Pupil Cloud) gaze.csv: gaze position on surface x/y
// [normalized], (0, 0) the surface's top left and (1, 1) its bottom right;
// empty when the surface was not found (lost). The surface is the display
// the participant watched: it maps to the input frame. Gaze off the surface
// keeps its position (off the frame).
std::vector<GazeSample> parse_neon_surface(const std::string& text, const std::string& name,
                                           const GazeImportOptions& o, GazeNotes& notes) {
  DelimitedTable t = parse_delimited(text, ',');
  keep_recording(t, t.column("recording id"), o.recording, name, notes);
  const int ct = require(t, "timestamp [ns]", name), cx = require(t, "gaze position on surface x [normalized]", name),
            cy = require(t, "gaze position on surface y [normalized]", name);
  return neon_rows(t, name, ct, cx, cy, -1, o.frame_width, o.frame_height);
}

size_t apply_blinks(const std::string& text, const std::string& name, const std::string& recording,
                    std::vector<GazeSample>& samples) {
  DelimitedTable t = parse_delimited(text, ',');
  GazeNotes ignored;
  keep_recording(t, t.column("recording id"), recording, name, ignored);
  // Pupil Core: start_timestamp / end_timestamp (s); Neon: start / end timestamp [ns].
  const bool neon = t.column("start timestamp [ns]") >= 0;
  const int cs = neon ? t.column("start timestamp [ns]") : require(t, "start_timestamp", name);
  const int ce = neon ? require(t, "end timestamp [ns]", name) : require(t, "end_timestamp", name);
  const double unit = neon ? 1e-9 : 1.0;
  std::vector<std::pair<double, double>> blinks;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::string where = name + ":" + std::to_string(t.line_numbers[r]);
    double a, b;
    if (!parse_number(field(t.rows[r], cs, where), a) || !parse_number(field(t.rows[r], ce, where), b) || b < a)
      throw InputError(where + ": a blink needs a start and an end time, in order");
    blinks.emplace_back(a * unit, b * unit);
  }
  for (GazeSample& s : samples)
    for (const auto& [a, b] : blinks)
      if (s.t_s >= a && s.t_s <= b) s.state = EyeState::kClosed;
  return blinks.size();
}

}  // namespace eyestream::io
