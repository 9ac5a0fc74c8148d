#include "io/gaze_csv.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "io/error.hpp"
#include "io/staged_file.hpp"

namespace eyestream::io {

namespace {

std::string trim(const std::string& s) {
  size_t b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, ',')) out.push_back(trim(field));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

bool parse_number(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(out);
}

struct Columns {
  int t = -1, x = -1, y = -1, event = -1;
};

Columns read_header(const std::string& line, const std::string& where) {
  Columns c;
  std::vector<std::string> names = split_fields(line);
  for (int i = 0; i < int(names.size()); ++i) {
    if (names[i] == "t")
      c.t = i;
    else if (names[i] == "x")
      c.x = i;
    else if (names[i] == "y")
      c.y = i;
    else if (names[i] == "event")
      c.event = i;
  }
  if (c.t < 0 || c.x < 0 || c.y < 0)
    throw InputError(where + ": header must name the columns t,x,y (and optionally event)");
  return c;
}

EyeState parse_event(const std::string& e, const std::string& where) {
  if (e.empty() || e == "fixation" || e == "saccade") return EyeState::kOpen;
  if (e == "blink") return EyeState::kClosed;
  if (e == "lost") return EyeState::kLost;
  throw InputError(where + ": unknown event '" + e + "' (expected fixation, saccade, blink or lost)");
}

}  // namespace

std::vector<GazeSample> parse_gaze_csv(const std::string& text, const std::string& name, GazeUnits units,
                                       int frame_width, int frame_height) {
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  Columns cols;
  bool have_header = false;
  std::vector<GazeSample> out;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string where = name + ":" + std::to_string(line_no);
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    if (!have_header) {
      cols = read_header(line, where);
      have_header = true;
      continue;
    }
    std::vector<std::string> f = split_fields(line);
    int needed = std::max({cols.t, cols.x, cols.y}) + 1;
    if (int(f.size()) < needed)
      throw InputError(where + ": expected " + std::to_string(needed) + " fields, found " + std::to_string(f.size()));
    GazeSample s;
    if (!parse_number(f[cols.t], s.t_s)) throw InputError(where + ": time '" + f[cols.t] + "' is not a number");
    s.state = (cols.event >= 0 && cols.event < int(f.size())) ? parse_event(f[cols.event], where) : EyeState::kOpen;
    bool has_x = parse_number(f[cols.x], s.x), has_y = parse_number(f[cols.y], s.y);
    if (s.state == EyeState::kOpen && !(has_x && has_y))
      throw InputError(where + ": position '" + f[cols.x] + "," + f[cols.y] + "' is not a pair of numbers");
    if (units == GazeUnits::kNormalised) {
      s.x *= frame_width;
      s.y *= frame_height;
    }
    if (!out.empty() && s.t_s <= out.back().t_s)
      throw InputError(where + ": time " + f[cols.t] + " s does not come after the previous sample's");
    out.push_back(s);
  }
  if (!have_header) throw InputError(name + ": empty gaze log (expected a header t,x,y[,event])");
  return out;
}

std::vector<GazeSample> read_gaze_csv(const std::string& path, GazeUnits units, int frame_width, int frame_height) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open gaze log");
  protect_input(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_gaze_csv(ss.str(), path, units, frame_width, frame_height);
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
