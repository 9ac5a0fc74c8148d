#include "io/gaze_import.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <fstream>
#include <sstream>

#include "io/delimited_table.hpp"
#include "io/error.hpp"
#include "io/staged_file.hpp"

namespace eyestream::io {

GazeFormat detect_gaze_format(const std::string& text) {
  const std::string head = text.substr(0, std::min<size_t>(text.size(), 4096));
  // Pupil Player: gaze_timestamp,world_index,... (older: timestamp,index,...).
  if (head.find("norm_pos_x") != std::string::npos && head.find("timestamp") != std::string::npos)
    return GazeFormat::kPupilCore;
  if (head.find("timestamp [ns]") != std::string::npos && head.find("gaze position on surface x") != std::string::npos)
    return GazeFormat::kNeonSurface;
  if (head.find("timestamp [ns]") != std::string::npos && head.find("gaze x [px]") != std::string::npos)
    return GazeFormat::kNeon;
  if (head.find("Recording timestamp") != std::string::npos && head.find('\t') != std::string::npos)
    return GazeFormat::kTobii;
  if (head.rfind("** ", 0) == 0 || head.find("\nMSG") != std::string::npos ||
      head.find("START\t") != std::string::npos || head.find("\nSBLINK") != std::string::npos)
    return GazeFormat::kEyeLink;
  return GazeFormat::kNative;
}

namespace {

// The text without a UTF-8 byte-order mark and with LF line ends.
std::string plain_text(const std::string& raw) {
  std::string text = raw.rfind("\xEF\xBB\xBF", 0) == 0 ? raw.substr(3) : raw;
  text.erase(std::remove(text.begin(), text.end(), '\r'), text.end());
  return text;
}

}  // namespace

void keep_recording(DelimitedTable& t, int column, const std::string& choice, const std::string& name,
                    GazeNotes& notes) {
  if (column < 0) {
    if (!choice.empty()) notes.push_back("--gaze-recording: " + name + " names no recordings; read whole");
    return;
  }
  std::vector<std::string> names;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::vector<std::string>& row = t.rows[r];
    if (column >= int(row.size()) || row[size_t(column)].empty())
      throw InputError(name + ":" + std::to_string(t.line_numbers[r]) + ": no " + t.header[size_t(column)]);
    const std::string& id = row[size_t(column)];
    if (std::find(names.begin(), names.end(), id) == names.end()) names.push_back(id);
  }
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  const bool chosen = std::find(names.begin(), names.end(), choice) != names.end();
  if (!choice.empty() && !chosen)
    throw InputError(name + ": no recording '" + choice + "' (--gaze-recording, or the gaze log's own); it holds " +
                     list);
  if (choice.empty() && names.size() > 1)
    throw InputError(name + ": holds " + std::to_string(names.size()) + " recordings (" + list +
                     "); choose one with --gaze-recording");
  if (!chosen) return;
  DelimitedTable kept = t;
  kept.rows.clear();
  kept.line_numbers.clear();
  for (size_t r = 0; r < t.rows.size(); ++r)
    if (column < int(t.rows[r].size()) && t.rows[r][size_t(column)] == choice) {
      kept.rows.push_back(t.rows[r]);
      kept.line_numbers.push_back(t.line_numbers[r]);
    }
  if (names.size() > 1) notes.push_back("recording " + choice + " of " + std::to_string(names.size()));
  t = std::move(kept);
}

namespace {

// The recording id of a Neon table's first row ("" when it has none).
std::string neon_recording(const std::string& text) {
  const DelimitedTable t = parse_delimited(text, ',');
  const int c = t.column("recording id");
  return c >= 0 && !t.rows.empty() && c < int(t.rows.front().size()) ? t.rows.front()[size_t(c)] : "";
}

// The recording a file beside the log (blinks, pupils) is read for: the
// one chosen with --gaze-recording, else, when the file holds several,
// the gaze log's own; "" (the file's only one) otherwise.
std::string companion_recording(const std::string& companion, const std::string& choice, const std::string& log) {
  if (!choice.empty()) return choice;
  const DelimitedTable t = parse_delimited(companion, ',');
  const int c = t.column("recording id");
  if (c < 0) return "";
  const std::string* first = nullptr;  // the first row's recording (rows too short have none)
  for (const std::vector<std::string>& row : t.rows) {
    if (c >= int(row.size())) continue;
    if (!first) first = &row[size_t(c)];
    else if (row[size_t(c)] != *first) return neon_recording(log);
  }
  return "";
}

}  // namespace

std::vector<GazeSample> parse_gaze(const std::string& raw, const std::string& name, const GazeImportOptions& o,
                                   GazeRead* read) {
  const std::string text = plain_text(raw);
  const GazeFormat format = o.format == GazeFormat::kAuto ? detect_gaze_format(text) : o.format;
  GazeRead local;
  GazeRead& info = read ? *read : local;
  info.format = format;
  if (format != GazeFormat::kPupilCore && format != GazeFormat::kNeon && format != GazeFormat::kNeonSurface &&
      o.blinks != "auto" && o.blinks != "none")
    throw UsageError("--gaze-blinks " + o.blinks + ": blinks files go with Pupil Core and Neon exports; " + name +
                     " is not one");
  if (format != GazeFormat::kPupilCore && format != GazeFormat::kNeon && format != GazeFormat::kNeonSurface &&
      o.pupils != "auto" && o.pupils != "none")
    throw UsageError("--gaze-pupils " + o.pupils + ": pupil files go with Pupil Core and Neon exports; " + name +
                     " is not one");
  if (!o.sync_message.empty() && format != GazeFormat::kEyeLink)
    throw UsageError("--gaze-sync-message: only EyeLink ASC files carry messages (use --gaze-sync)");
  if (!o.sync_message.empty() && o.sync_clock)
    throw UsageError("--gaze-sync and --gaze-sync-message both set time 0: give one");
  if (!o.recording.empty() && format != GazeFormat::kNeon && format != GazeFormat::kNeonSurface &&
      format != GazeFormat::kTobii)
    throw UsageError("--gaze-recording " + o.recording + ": only Neon and Tobii exports hold several recordings; " +
                     name + " does not");
  if (format == GazeFormat::kNative) {
    std::vector<GazeSample> s = parse_gaze_csv(text, name, o.units, o.frame_width, o.frame_height);
    for (GazeSample& g : s) g.t_s += o.offset_s;
    return s;
  }
  std::optional<double> message_time;
  GazeNotes& notes = info.notes;
  std::vector<GazeSample> s = format == GazeFormat::kPupilCore     ? parse_pupil_core(text, name, o, notes)
                              : format == GazeFormat::kNeon        ? parse_neon(text, name, o, notes)
                              : format == GazeFormat::kNeonSurface ? parse_neon_surface(text, name, o, notes)
                              : format == GazeFormat::kTobii       ? parse_tobii(text, name, o, notes)
                                                                   : parse_eyelink(text, name, o, notes, &message_time);
  if (s.empty()) throw InputError(name + ": no gaze samples");
  const bool pupil_labs =
      format == GazeFormat::kPupilCore || format == GazeFormat::kNeon || format == GazeFormat::kNeonSurface;
  if (pupil_labs && !o.blinks_text.empty()) {
    const std::string blinks = plain_text(o.blinks_text);
    const size_t n = apply_blinks(blinks, o.blinks_name, companion_recording(blinks, o.recording, text), s);
    notes.push_back(std::to_string(n) + " blinks from " + o.blinks_name);
  }
  if (pupil_labs && !o.pupils_name.empty()) {
    const std::string pupils = plain_text(o.pupils_text);
    GazeImportOptions which = o;
    which.recording = companion_recording(pupils, o.recording, text);
    const size_t n = apply_pupils(pupils, o.pupils_name, which, s, notes);
    notes.push_back("pupil diameters from " + o.pupils_name + " for " + std::to_string(n) + " of " +
                    std::to_string(s.size()) + " samples");
  }
  std::stable_sort(s.begin(), s.end(), [](const GazeSample& a, const GazeSample& b) { return a.t_s < b.t_s; });
  std::vector<GazeSample> unique;
  for (const GazeSample& g : s) {
    if (!unique.empty() && unique.back().t_s == g.t_s)
      unique.back() = g;
    else
      unique.push_back(g);
  }
  const double zero = message_time ? *message_time : o.sync_clock.value_or(unique.front().t_s);
  for (GazeSample& g : unique) g.t_s = g.t_s - zero + o.offset_s;
  return unique;
}

namespace {

std::optional<std::string> read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

namespace {

// A file a Pupil Player or Neon export keeps beside its gaze: `choice`
// "auto" reads the first of `names` beside the log that is there, anything
// but "none" is the file's path or the export's folder (an InputError when
// nothing can be read; `option` names it).
void read_companion(const std::string& log, const std::string& choice, const std::vector<std::string>& names,
                    const std::string& option, std::string& text, std::string& name) {
  if (!text.empty() || choice == "none") return;
  const bool beside = choice == "auto";
  std::vector<std::filesystem::path> candidates;
  const std::filesystem::path folder = beside ? std::filesystem::path(log).parent_path() : std::filesystem::path(choice);
  if (beside || std::filesystem::is_directory(folder))  // an export's folder
    for (const std::string& n : names) candidates.push_back(folder / n);
  else
    candidates.push_back(choice);
  for (const std::filesystem::path& c : candidates) {
    if (beside && std::filesystem::path(log).filename() == c.filename()) continue;  // the log itself
    if (const std::optional<std::string> t = read_text(c)) {
      protect_input(c.string());
      text = *t;
      name = c.string();
      return;
    }
  }
  if (!beside) throw InputError(choice + ": cannot open the file " + option + " names");
}

}  // namespace

std::vector<GazeSample> read_gaze(const std::string& path, const GazeImportOptions& options, GazeRead* read) {
  const std::optional<std::string> text = read_text(path);
  if (!text) throw InputError(path + ": cannot open gaze log");
  protect_input(path);
  GazeImportOptions o = options;
  read_companion(path, o.blinks, {"blinks.csv"}, "--gaze-blinks", o.blinks_text, o.blinks_name);
  if (o.want_pupils)
    read_companion(path, o.pupils, {"pupil_positions.csv", "3d_eye_states.csv"}, "--gaze-pupils", o.pupils_text,
                   o.pupils_name);
  return parse_gaze(*text, path, o, read);
}

}  // namespace eyestream::io
