// SR Research EyeLink ASC files (edf2asc): sample lines "time x y pupil"
// (binocular: "time xl yl pl xr yr pr"; the pupil in the tracker's own
// units, area or diameter as the "PUPIL AREA|DIAMETER" line says, area
// when none does, read when a scale to mm is given: diameter = scale x
// diameter units, or scale x sqrt(area units)), "." for missing values, SBLINK /
// EBLINK events, screen size from the DISPLAY_COORDS message; times in ms
// (fractional at 2 kHz). Real files carry calibration blocks whose values
// continue on indented lines: samples are read only from lines that start
// with a digit in column 0 inside START ... END recording blocks (a file
// with no START line, an excerpt, is read whole).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>

#include "io/delimited_table.hpp"
#include "io/error.hpp"
#include "io/gaze_import.hpp"

namespace eyestream::io {

std::vector<GazeSample> parse_eyelink(const std::string& text, const std::string& name, const GazeImportOptions& o,
                                      GazeNotes& notes, std::optional<double>* sync_s) {
  if (o.eye != "left" && o.eye != "right" && o.eye != "average")
    throw UsageError("--gaze-eye must be left, right or average, not '" + o.eye + "'");
  bool binocular = false, said = false;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  bool blinking = false;
  const bool blocks = text.rfind("START", 0) == 0 || text.find("\nSTART") != std::string::npos;
  bool recording = !blocks;
  bool display_coords = false, gaze_coords = false;
  bool pupil_area = true;  // EyeLink's default; "PUPIL DIAMETER" says otherwise
  double screen_w = o.source_width, screen_h = o.source_height;
  std::vector<GazeSample> raw;  // positions in screen pixels until the end
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.empty()) continue;
    const std::string where = name + ":" + std::to_string(line_no);
    if (w[0] == "MSG") {
      // The screen: DISPLAY_COORDS, else GAZE_COORDS (the tracker's own
      // record of the gaze's pixel range), unless given.
      for (size_t i = 0; i + 4 < w.size(); ++i)
        if ((w[i] == "DISPLAY_COORDS" || (w[i] == "GAZE_COORDS" && !display_coords)) && o.source_width <= 0) {
          double l, t, r, b;
          if (parse_number(w[i + 1], l) && parse_number(w[i + 2], t) && parse_number(w[i + 3], r) &&
              parse_number(w[i + 4], b))
            screen_w = r - l + 1, screen_h = b - t + 1, display_coords = w[i] == "DISPLAY_COORDS",
            gaze_coords = true;
        }
      // "MSG time [offset] text": Experiment Builder writes an integer offset
      // when the message was logged after its event, at time - offset.
      if (!sync_s || *sync_s || o.sync_message.empty() || w.size() < 3) continue;  // "MSG time text" at least
      double t, offset = 0;
      const bool has_offset = w.size() >= 4 && w[2].find_first_not_of("-0123456789") == std::string::npos &&
                              parse_number(w[2], offset);
      const std::string& before_text = w[has_offset ? 2 : 1];  // the text starts after this word
      const size_t text_at =
          line.find(before_text, line.find(w[1]) + (has_offset ? w[1].size() : 0)) + before_text.size();
      if (line.find(o.sync_message, text_at) != std::string::npos && parse_number(w[1], t))
        *sync_s = (t - offset) * 1e-3;  // the stimulus onset the user marked
      continue;
    }
    if (w[0] == "PUPIL" && w.size() >= 2) {
      pupil_area = w[1] != "DIAMETER";
      continue;
    }
    if (w[0] == "START" || w[0] == "END") {
      recording = w[0] == "START" || !blocks;
      if (w[0] == "START") {
        const bool has_left = std::find(w.begin(), w.end(), "LEFT") != w.end(),
                   has_right = std::find(w.begin(), w.end(), "RIGHT") != w.end();
        binocular = has_left && has_right;
        if (!binocular && o.eye != "average" && (has_left || has_right) && has_left != (o.eye == "left"))
          throw UsageError("--gaze-eye " + o.eye + ": " + where + " records only the " +
                           (has_left ? "left" : "right") + " eye");
        if (binocular && !said) notes.push_back("EyeLink: binocular, " + (o.eye == "average" ? std::string("the two eyes averaged") : o.eye + " eye") + " (--gaze-eye)");
        said = said || binocular;
      }
      continue;
    }
    if (w[0] == "SBLINK" && w.size() >= 3) {
      double t;
      if (!parse_number(w[2], t)) throw InputError(where + ": SBLINK time is not a number");
      blinking = true;
      raw.push_back({t * 1e-3, 0, 0, EyeState::kClosed});
      continue;
    }
    if (w[0] == "EBLINK") {
      blinking = false;
      continue;
    }
    // Other events, headers, indented continuation lines, and anything
    // outside the recording blocks.
    if (!recording || !std::isdigit(static_cast<unsigned char>(line[0]))) continue;
    GazeSample s;
    double t, x, y;
    if (!parse_number(w[0], t)) throw InputError(where + ": sample time '" + w[0] + "' is not a number");
    s.t_s = t * 1e-3;
    // Binocular lines: "time xl yl pl xr yr pr"; the chosen eye, or the
    // mean of the two (the one seen when the other is missing).
    // A position is a number or "." (missing); anything else is a malformed line.
    // (edf2asc -miss NaN writes "nan"; the right eye's columns are checked
    // only when a START line says the file is binocular.)
    for (size_t i : {size_t(1), size_t(2), size_t(4), size_t(5)}) {
      if (i >= w.size() || (i >= 4 && !binocular)) continue;
      double v;
      const std::string& f = w[i];
      const bool missing = f == "." || f == "nan" || f == "NaN" || f == "-nan" || f == "NAN";
      if (!missing && !parse_number(f, v))
        throw InputError(where + ": sample position '" + f + "' is neither a number nor '.'");
    }
    double xl, yl, xr, yr;
    const bool left = w.size() >= 3 && parse_number(w[1], xl) && parse_number(w[2], yl);
    // (An excerpt without START says nothing: a line of seven or more
    // fields, "time xl yl pl xr yr pr ...", is binocular.)
    const bool both = binocular || (!blocks && w.size() >= 7);
    const bool right = both && w.size() >= 6 && parse_number(w[4], xr) && parse_number(w[5], yr);
    const bool use_left = left && (!both || o.eye != "right"), use_right = right && o.eye != "left";
    // The pupil, of the eye or eyes the gaze is taken from.
    double pl = 0.0, pr = 0.0;
    const bool pupil_left = use_left && w.size() >= 4 && parse_number(w[3], pl) && pl > 0.0;
    const bool pupil_right = use_right && w.size() >= 7 && parse_number(w[6], pr) && pr > 0.0;
    if (o.pupil_scale_mm > 0.0 && (pupil_left || pupil_right)) {
      const auto diameter = [&](double v) { return o.pupil_scale_mm * (pupil_area ? std::sqrt(v) : v); };
      s.pupil_mm = pupil_left && pupil_right ? 0.5 * (diameter(pl) + diameter(pr)) : diameter(pupil_left ? pl : pr);
    }
    if (use_left && use_right)
      x = 0.5 * (xl + xr), y = 0.5 * (yl + yr);
    else if (use_left)
      x = xl, y = yl;
    else if (use_right)
      x = xr, y = yr;
    if (blinking)
      s.state = EyeState::kClosed;
    else if (!use_left && !use_right)
      s.state = EyeState::kLost;
    else
      s.x = x, s.y = y;
    raw.push_back(s);
  }
  if (!gaze_coords && (o.source_width <= 0 || o.source_height <= 0))
    throw InputError(name + ": no DISPLAY_COORDS or GAZE_COORDS message gives the screen the gaze is in; give its size with "
                            "--gaze-source-width and --gaze-source-height");
  if (!o.sync_message.empty() && sync_s && !*sync_s)
    throw InputError(name + ": no MSG line contains '" + o.sync_message + "' (--gaze-sync-message)");
  const double sx = screen_w > 0 ? o.frame_width / screen_w : 1.0, sy = screen_h > 0 ? o.frame_height / screen_h : 1.0;
  for (GazeSample& s : raw) s.x *= sx, s.y *= sy;
  return raw;
}

}  // namespace eyestream::io
