// Pupil diameters recorded beside Pupil Labs gaze exports: Pupil Core's
// pupil_positions.csv and Neon's 3d_eye_states.csv (gaze_import.hpp).
#include <algorithm>
#include <cmath>

#include "io/delimited_table.hpp"
#include "io/error.hpp"
#include "io/gaze_import.hpp"

namespace eyestream::io {

namespace {

using Series = std::vector<std::pair<double, double>>;  // (export clock s, diameter mm)

// Two pupil samples further apart than this are not interpolated between:
// the gap (the eye lost for long) is left to the timeline's bridge.
constexpr double kLongestGap_s = 1.0;

// The diameter at t from the neighbouring samples, NaN in a gap.
double at(const Series& s, double t) {
  const auto after = std::lower_bound(s.begin(), s.end(), t, [](const auto& p, double v) { return p.first < v; });
  if (after != s.end() && after->first == t) return after->second;
  if (after == s.begin() || after == s.end()) return NAN;
  const auto before = after - 1;
  if (after->first - before->first > kLongestGap_s) return NAN;
  const double f = (t - before->first) / (after->first - before->first);
  return before->second + f * (after->second - before->second);
}

// A human pupil's diameter (mm); the 3d model's outliers beyond are none.
constexpr double kFewest_mm = 1.0, kMost_mm = 10.0;

void add(Series& s, double t, const std::string& value, size_t& outliers) {
  double d;
  if (!parse_number(value, d) || !(d > 0.0)) return;  // empty, NaN or 0: no pupil
  if (d < kFewest_mm || d > kMost_mm) {
    ++outliers;
    return;
  }
  s.emplace_back(t, d);
}

const std::string& cell(const std::vector<std::string>& row, int c) {
  static const std::string none;
  return c >= 0 && c < int(row.size()) ? row[size_t(c)] : none;
}

int require(const DelimitedTable& t, const std::string& column, const std::string& name, const std::string& what) {
  const int c = t.column(column);
  if (c < 0) throw InputError(name + ":" + std::to_string(t.header_line) + ": no column '" + column + "' (" + what + ")");
  return c;
}

}  // namespace

size_t apply_pupils(const std::string& text, const std::string& name, const GazeImportOptions& o,
                    std::vector<GazeSample>& samples, GazeNotes& notes) {
  DelimitedTable t = parse_delimited(text, ',');
  if (t.rows.empty()) throw InputError(name + ": holds no pupil rows (--gaze-pupils none reads none)");
  Series left, right;  // Pupil Core: eye1 is the left eye, eye0 the right
  size_t outliers = 0;
  if (t.column("timestamp [ns]") >= 0) {
    // Neon: timestamp [ns]; pupil diameter left/right [mm] (older
    // exports: one "pupil diameter [mm]", kept as both eyes').
    GazeNotes ignored;
    keep_recording(t, t.column("recording id"), o.recording, name, ignored);
    const int ct = t.column("timestamp [ns]");
    const int one = t.column("pupil diameter [mm]");
    const int cl = one >= 0 ? one : require(t, "pupil diameter left [mm]", name, "a Neon 3d_eye_states.csv");
    const int cr = one >= 0 ? one : require(t, "pupil diameter right [mm]", name, "a Neon 3d_eye_states.csv");
    for (size_t r = 0; r < t.rows.size(); ++r) {
      double ns;
      if (!parse_number(cell(t.rows[r], ct), ns))
        throw InputError(name + ":" + std::to_string(t.line_numbers[r]) + ": timestamp [ns] is not a number");
      if (o.eye != "right" || one >= 0) add(left, ns * 1e-9, cell(t.rows[r], cl), outliers);
      if (one < 0 && o.eye != "left") add(right, ns * 1e-9, cell(t.rows[r], cr), outliers);
    }
    if (one >= 0) right = left;  // one diameter for both eyes
  } else {
    // Pupil Core: pupil_timestamp (s, the gaze's clock), eye_id, confidence,
    // diameter_3d (mm, from the 3d eye model; the 2d detector's rows, whose
    // method names no 3d model, have none).
    const std::string what = "a Pupil Core pupil_positions.csv";
    const int ct = require(t, "pupil_timestamp", name, what), ce = require(t, "eye_id", name, what),
              cc = require(t, "confidence", name, what), cd = require(t, "diameter_3d", name, what);
    const int cm = t.column("method");
    for (size_t r = 0; r < t.rows.size(); ++r) {
      const std::string where = name + ":" + std::to_string(t.line_numbers[r]);
      double time, eye, confidence;
      if (!parse_number(cell(t.rows[r], ct), time)) throw InputError(where + ": pupil_timestamp is not a number");
      if (!parse_number(cell(t.rows[r], ce), eye) || (eye != 0.0 && eye != 1.0))
        throw InputError(where + ": eye_id is not 0 or 1");
      if (cm >= 0 && cell(t.rows[r], cm).find("3d") == std::string::npos) continue;
      if (!parse_number(cell(t.rows[r], cc), confidence)) throw InputError(where + ": confidence is not a number");
      const bool used = o.eye == "average" || (o.eye == "left") == (eye == 1.0);  // (outliers of an eye read)
      if (used && confidence >= o.min_confidence) add(eye == 1.0 ? left : right, time, cell(t.rows[r], cd), outliers);
    }
  }
  const auto by_time = [](const auto& a, const auto& b) { return a.first < b.first; };
  std::stable_sort(left.begin(), left.end(), by_time);
  std::stable_sort(right.begin(), right.end(), by_time);
  const bool use_left = o.eye != "right", use_right = o.eye != "left";
  size_t given = 0;
  for (GazeSample& s : samples) {
    const double l = use_left ? at(left, s.t_s) : NAN, r = use_right ? at(right, s.t_s) : NAN;
    s.pupil_mm = std::isnan(l) ? r : std::isnan(r) ? l : 0.5 * (l + r);
    given += !std::isnan(s.pupil_mm);
  }
  if (outliers > 0)
    notes.push_back(std::to_string(outliers) + " pupil diameters outside 1-10 mm in " + name + " left out");
  return given;
}

}  // namespace eyestream::io
