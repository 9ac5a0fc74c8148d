// Tobii Pro Lab TSV exports: Recording timestamp (ms or us, per the
// header), Gaze point X/Y in pixels of the recorded media, Validity
// left/right; decimal commas accepted.
#include "io/delimited_table.hpp"
#include "io/error.hpp"
#include "io/gaze_import.hpp"

namespace eyestream::io {

std::vector<GazeSample> parse_tobii(const std::string& text, const std::string& name, const GazeImportOptions& o) {
  const DelimitedTable t = parse_delimited(text, '\t');
  const int ct = t.column("Recording timestamp", true), cx = t.column("Gaze point X", true),
            cy = t.column("Gaze point Y", true);
  if (ct < 0 || cx < 0 || cy < 0)
    throw InputError(name + ":" + std::to_string(t.header_line) +
                     ": a Tobii export needs Recording timestamp, Gaze point X and Gaze point Y columns");
  const std::string& unit = t.header[size_t(ct)];
  const bool micro = unit.find("us]") != std::string::npos || unit.find("\xce\xbcs]") != std::string::npos ||
                     unit.find("\xc2\xb5s]") != std::string::npos;
  const double to_s = micro ? 1e-6 : 1e-3;
  const int cl = t.column("Validity left"), cr = t.column("Validity right");
  const double sx = o.source_width > 0 ? double(o.frame_width) / o.source_width : 1.0;
  const double sy = o.source_height > 0 ? double(o.frame_height) / o.source_height : 1.0;
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
    out.push_back(s);
  }
  return out;
}

}  // namespace eyestream::io
