// Tobii Pro Lab TSV exports: Recording timestamp (ms or us, per the
// header; without a unit, from the samples' spacing), Gaze point X/Y in
// pixels of the recorded media, Validity left/right, Pupil diameter
// left/right (mm, their mean); decimal commas accepted; one recording of
// several (Recording name).
#include <algorithm>
#include <cmath>
#include <utility>

#include "io/delimited_table.hpp"
#include "io/error.hpp"
#include "io/gaze_import.hpp"

namespace eyestream::io {

namespace {

// The median spacing of a column's successive numbers (0 when fewer than two).
double median_spacing(const DelimitedTable& t, int c) {
  std::vector<double> values, steps;
  for (const std::vector<std::string>& row : t.rows) {
    double v;
    if (c < int(row.size()) && parse_number(row[size_t(c)], v, true)) values.push_back(v);
  }
  for (size_t i = 1; i < values.size(); ++i)
    if (values[i] > values[i - 1]) steps.push_back(values[i] - values[i - 1]);
  if (steps.empty()) return 0.0;
  std::nth_element(steps.begin(), steps.begin() + long(steps.size() / 2), steps.end());
  return steps[steps.size() / 2];
}

}  // namespace

std::vector<GazeSample> parse_tobii(const std::string& text, const std::string& name, const GazeImportOptions& o,
                                    GazeNotes& notes) {
  DelimitedTable t = parse_delimited(text, '\t');
  keep_recording(t, t.column("Recording name"), o.recording, name, notes);
  const int ct = t.column("Recording timestamp", true), cx = t.column("Gaze point X", true),
            cy = t.column("Gaze point Y", true);
  if (ct < 0 || cx < 0 || cy < 0)
    throw InputError(name + ":" + std::to_string(t.header_line) +
                     ": a Tobii export needs Recording timestamp, Gaze point X and Gaze point Y columns");
  const std::string& unit = t.header[size_t(ct)];
  bool micro = unit.find("us]") != std::string::npos || unit.find("\xce\xbcs]") != std::string::npos ||
               unit.find("\xc2\xb5s]") != std::string::npos;
  if (unit.find('[') == std::string::npos) {
    // No unit: Tobii trackers sample at 30 to 1200 Hz, 0.8 to 33 ms apart,
    // so a median spacing of 200 or more can only be microseconds.
    const double spacing = median_spacing(t, ct);
    micro = spacing >= 200.0;
    char note[160];
    std::snprintf(note, sizeof note, "Recording timestamp has no unit: %s, from the samples' median spacing of %g",
                  micro ? "microseconds" : "milliseconds", spacing);
    notes.push_back(note);
  }
  const double to_s = micro ? 1e-6 : 1e-3;
  const int cl = t.column("Validity left"), cr = t.column("Validity right");
  const int pl = t.column("Pupil diameter left", true), pr = t.column("Pupil diameter right", true);
  // The screen the gaze is in: --gaze-source-width/height, else the export's
  // "Recording resolution width/height" (the first row that has them), else
  // the frame itself.
  double source_w = o.source_width, source_h = o.source_height;
  const int rw = t.column("Recording resolution width", true), rh = t.column("Recording resolution height", true);
  if (rw >= 0 && rh >= 0 && (source_w <= 0 || source_h <= 0))
    for (size_t r = 0; r < t.rows.size(); ++r) {
      const std::vector<std::string>& row = t.rows[r];
      if (rw >= int(row.size()) || rh >= int(row.size()) || (row[size_t(rw)].empty() && row[size_t(rh)].empty()))
        continue;  // a row without them (an event row)
      double w = 0, h = 0;
      if (!parse_number(row[size_t(rw)], w, true) || !parse_number(row[size_t(rh)], h, true) || !(w > 0) || !(h > 0))
        throw InputError(name + ":" + std::to_string(t.line_numbers[r]) + ": Recording resolution '" +
                         row[size_t(rw)] + "x" + row[size_t(rh)] + "' is not a screen size in pixels");
      {
        const bool both = source_w <= 0 && source_h <= 0;
        if (source_w <= 0) source_w = w;
        if (source_h <= 0) source_h = h;
        char note[160];
        std::snprintf(note, sizeof note, "the screen is %gx%g px, %s from Recording resolution", source_w, source_h,
                      both ? "both" : "the side not given");
        notes.push_back(note);
        break;
      }
    }
  const double sx = source_w > 0 ? double(o.frame_width) / source_w : 1.0;
  const double sy = source_h > 0 ? double(o.frame_height) / source_h : 1.0;
  auto invalid = [&](const std::vector<std::string>& row, int c) {
    return c >= 0 && c < int(row.size()) && row[size_t(c)] == "Invalid";
  };
  std::vector<GazeSample> out;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::vector<std::string>& row = t.rows[r];
    const std::string where = name + ":" + std::to_string(t.line_numbers[r]);
    GazeSample s;
    double clock, x, y;
    if (ct >= int(row.size()) || !parse_number(row[size_t(ct)], clock, true))
      throw InputError(where + ": Recording timestamp is not a number");
    s.t_s = clock * to_s;
    const bool position = cx < int(row.size()) && cy < int(row.size()) && parse_number(row[size_t(cx)], x, true) &&
                          parse_number(row[size_t(cy)], y, true);
    place(s, position && !(invalid(row, cl) && invalid(row, cr)), x, y, sx, sy);
    // The pupil: the mean of the valid eyes' diameters.
    double sum = 0.0, d;
    int eyes = 0;
    for (const auto& [c, validity] : {std::pair{pl, cl}, std::pair{pr, cr}})
      if (c >= 0 && c < int(row.size()) && !invalid(row, validity) && parse_number(row[size_t(c)], d, true) && d > 0.0)
        sum += d, ++eyes;
    if (eyes > 0) s.pupil_mm = sum / eyes;
    out.push_back(s);
  }
  return out;
}

}  // namespace eyestream::io
