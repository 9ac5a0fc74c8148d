#include "io/gaze_import.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "io/error.hpp"
#include "io/staged_file.hpp"

namespace eyestream::io {

GazeFormat detect_gaze_format(const std::string& text) {
  const std::string head = text.substr(0, std::min<size_t>(text.size(), 4096));
  if (head.find("gaze_timestamp") != std::string::npos && head.find("norm_pos_x") != std::string::npos)
    return GazeFormat::kPupilCore;
  if (head.find("timestamp [ns]") != std::string::npos && head.find("gaze x [px]") != std::string::npos)
    return GazeFormat::kNeon;
  if (head.find("Recording timestamp") != std::string::npos && head.find('\t') != std::string::npos)
    return GazeFormat::kTobii;
  if (head.rfind("** ", 0) == 0 || head.find("\nMSG") != std::string::npos ||
      head.find("START\t") != std::string::npos || head.find("\nSBLINK") != std::string::npos)
    return GazeFormat::kEyeLink;
  return GazeFormat::kNative;
}

std::vector<GazeSample> parse_gaze(const std::string& text, const std::string& name, const GazeImportOptions& o,
                                   GazeFormat* format_read) {
  const GazeFormat format = o.format == GazeFormat::kAuto ? detect_gaze_format(text) : o.format;
  if (format_read) *format_read = format;
  if (format == GazeFormat::kNative) {
    std::vector<GazeSample> s = parse_gaze_csv(text, name, o.units, o.frame_width, o.frame_height);
    for (GazeSample& g : s) g.t_s += o.offset_s;
    return s;
  }
  if (!o.sync_message.empty() && format != GazeFormat::kEyeLink)
    throw UsageError("--gaze-sync-message: only EyeLink ASC files carry messages (use --gaze-sync)");
  std::optional<double> message_time;
  std::vector<GazeSample> s = format == GazeFormat::kPupilCore ? parse_pupil_core(text, name, o)
                              : format == GazeFormat::kNeon    ? parse_neon(text, name, o)
                              : format == GazeFormat::kTobii   ? parse_tobii(text, name, o)
                                                               : parse_eyelink(text, name, o, &message_time);
  if (s.empty()) throw InputError(name + ": no gaze samples");
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

std::vector<GazeSample> read_gaze(const std::string& path, const GazeImportOptions& o, GazeFormat* format) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open gaze log");
  protect_input(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_gaze(ss.str(), path, o, format);
}

}  // namespace eyestream::io
