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
    throw InputError(name + ": no recording '" + choice + "' (--gaze-recording); it holds " + list);
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
    const size_t n = apply_blinks(plain_text(o.blinks_text), o.blinks_name, o.recording, s);
    notes.push_back(std::to_string(n) + " blinks from " + o.blinks_name);
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

std::vector<GazeSample> read_gaze(const std::string& path, const GazeImportOptions& options, GazeRead* read) {
  const std::optional<std::string> text = read_text(path);
  if (!text) throw InputError(path + ": cannot open gaze log");
  protect_input(path);
  GazeImportOptions o = options;
  // Pupil Player and Neon export blinks beside the gaze; or a named file.
  if (o.blinks_text.empty() && o.blinks != "none") {
    const bool beside = o.blinks == "auto";
    std::filesystem::path blinks =
        beside ? std::filesystem::path(path).parent_path() / "blinks.csv" : std::filesystem::path(o.blinks);
    if (!beside && std::filesystem::is_directory(blinks)) blinks /= "blinks.csv";  // an export's folder
    const std::optional<std::string> b =
        beside && std::filesystem::path(path).filename() == "blinks.csv" ? std::nullopt : read_text(blinks);
    if (!b && !beside) throw InputError(o.blinks + ": cannot open the blinks file (--gaze-blinks)");
    if (b) {
      protect_input(blinks.string());
      o.blinks_text = *b;
      o.blinks_name = blinks.string();
    }
  }
  return parse_gaze(*text, path, o, read);
}

}  // namespace eyestream::io
