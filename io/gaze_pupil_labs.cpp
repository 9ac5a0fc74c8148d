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

// Pupil Core: gaze_timestamp (s, Pupil clock), confidence, norm_pos_x/y in
// 0..1 of the world camera with the origin at the bottom left.
std::vector<GazeSample> parse_pupil_core(const std::string& text, const std::string& name, const GazeImportOptions& o) {
  const DelimitedTable t = parse_delimited(text, ',');
  const int ct = require(t, "gaze_timestamp", name), cc = require(t, "confidence", name);
  const int cx = require(t, "norm_pos_x", name), cy = require(t, "norm_pos_y", name);
  std::vector<GazeSample> out;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::string where = name + ":" + std::to_string(t.line_numbers[r]);
    GazeSample s;
    double confidence, nx, ny;
    if (!parse_number(field(t.rows[r], ct, where), s.t_s)) throw InputError(where + ": gaze_timestamp is not a number");
    if (!parse_number(field(t.rows[r], cc, where), confidence))
      throw InputError(where + ": confidence is not a number");
    const bool position =
        parse_number(field(t.rows[r], cx, where), nx) && parse_number(field(t.rows[r], cy, where), ny);
    place(s, confidence >= o.min_confidence && position, nx, 1.0 - ny, o.frame_width, o.frame_height);
    out.push_back(s);
  }
  return out;
}

// Neon: timestamp [ns] (UTC), gaze x/y [px] in the 1600x1200 scene camera,
// worn (0/1 or true/false), blink id (non-empty during a blink).
std::vector<GazeSample> parse_neon(const std::string& text, const std::string& name, const GazeImportOptions& o) {
  const DelimitedTable t = parse_delimited(text, ',');
  const int ct = require(t, "timestamp [ns]", name), cx = require(t, "gaze x [px]", name),
            cy = require(t, "gaze y [px]", name);
  const int cw = t.column("worn"), cb = t.column("blink id");
  const double sx = double(o.frame_width) / (o.source_width > 0 ? o.source_width : 1600);
  const double sy = double(o.frame_height) / (o.source_height > 0 ? o.source_height : 1200);
  std::vector<GazeSample> out;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::string where = name + ":" + std::to_string(t.line_numbers[r]);
    GazeSample s;
    double ns, x, y;
    if (!parse_number(field(t.rows[r], ct, where), ns)) throw InputError(where + ": timestamp [ns] is not a number");
    s.t_s = ns * 1e-9;
    const bool blink = cb >= 0 && cb < int(t.rows[r].size()) && !t.rows[r][size_t(cb)].empty();
    const std::string worn = cw >= 0 && cw < int(t.rows[r].size()) ? t.rows[r][size_t(cw)] : "1";
    const bool position = parse_number(field(t.rows[r], cx, where), x) && parse_number(field(t.rows[r], cy, where), y);
    const bool worn_now = !(worn == "0" || worn == "false" || worn == "False");
    if (blink)
      s.state = EyeState::kClosed;
    else
      place(s, worn_now && position, x, y, sx, sy);
    out.push_back(s);
  }
  return out;
}

}  // namespace eyestream::io
