#include "io/gaze_csv.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "io/delimited_table.hpp"
#include "io/error.hpp"
#include "io/staged_file.hpp"

namespace eyestream::io {

namespace {

EyeState parse_event(const std::string& e, const std::string& where) {
  if (e.empty() || e == "fixation" || e == "saccade") return EyeState::kOpen;
  if (e == "blink") return EyeState::kClosed;
  if (e == "lost") return EyeState::kLost;
  throw InputError(where + ": unknown event '" + e + "' (expected fixation, saccade, blink or lost)");
}

}  // namespace

std::vector<GazeSample> parse_gaze_csv(const std::string& text, const std::string& name, GazeUnits units,
                                       int frame_width, int frame_height) {
  const DelimitedTable table = parse_delimited(text, ',');
  if (table.header.empty()) throw InputError(name + ": empty gaze log (expected a header t,x,y[,event])");
  const int ct = table.column("t"), cx = table.column("x"), cy = table.column("y"), ce = table.column("event");
  const int cp = table.column("pupil_mm");  // optional: the recorded pupil diameter
  if (ct < 0 || cx < 0 || cy < 0)
    throw InputError(name + ":" + std::to_string(table.header_line) +
                     ": header must name the columns t,x,y (and optionally event)");
  const int needed = std::max({ct, cx, cy}) + 1;
  std::vector<GazeSample> out;
  for (size_t r = 0; r < table.rows.size(); ++r) {
    const std::vector<std::string>& f = table.rows[r];
    const std::string where = name + ":" + std::to_string(table.line_numbers[r]);
    if (int(f.size()) < needed)
      throw InputError(where + ": expected " + std::to_string(needed) + " fields, found " + std::to_string(f.size()));
    if (f.size() > table.header.size())  // a column the header does not name would be dropped unseen
      throw InputError(where + ": " + std::to_string(f.size()) + " fields, but the header names " +
                       std::to_string(table.header.size()));
    GazeSample s;
    if (!parse_number(f[size_t(ct)], s.t_s)) throw InputError(where + ": time '" + f[size_t(ct)] + "' is not a number");
    s.state = (ce >= 0 && ce < int(f.size())) ? parse_event(f[size_t(ce)], where) : EyeState::kOpen;
    const bool has_x = parse_number(f[size_t(cx)], s.x), has_y = parse_number(f[size_t(cy)], s.y);
    if (s.state == EyeState::kOpen && !(has_x && has_y))
      throw InputError(where + ": position '" + f[size_t(cx)] + "," + f[size_t(cy)] + "' is not a pair of numbers");
    // (Empty or "nan", as numpy writes a missing value: no diameter.)
    const std::string pupil = cp >= 0 && cp < int(f.size()) ? f[size_t(cp)] : "";
    if (!pupil.empty() && pupil != "nan" && pupil != "NaN" && !parse_number(pupil, s.pupil_mm))
      throw InputError(where + ": pupil_mm '" + pupil + "' is not a number");
    if (units == GazeUnits::kNormalised) {
      s.x *= frame_width;
      s.y *= frame_height;
    }
    if (!out.empty() && s.t_s <= out.back().t_s)
      throw InputError(where + ": time " + f[size_t(ct)] + " s does not come after the previous sample's");
    out.push_back(s);
  }
  if (out.empty()) throw InputError(name + ": no gaze samples (a header and no rows)");
  return out;
}

void write_gaze_csv(const std::string& path, const std::vector<GazeSample>& samples) {
  std::ostringstream out;
  out.precision(9);
  out << "t,x,y,event\n";
  for (const GazeSample& s : samples) {
    const char* event = s.state == EyeState::kClosed ? "blink" : s.state == EyeState::kLost ? "lost" : "fixation";
    out << s.t_s << ',' << s.x << ',' << s.y << ',' << event << '\n';
  }
  std::string text = out.str();
  StagedFile file(path);
  write_all(file, std::vector<unsigned char>(text.begin(), text.end()));
  file.commit();
}

}  // namespace eyestream::io
