#include "pipeline/run/output_paths.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <regex>

#include "io/error.hpp"
#include "io/frame_sequence.hpp"
#include "io/staged_file.hpp"

namespace eyestream::pipeline {

namespace fs = std::filesystem;

namespace {

std::string normal(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path), ec);
  return (ec ? fs::absolute(path).lexically_normal() : p).string();
}

// A regular expression matching the files of a printf frame pattern.
std::regex pattern_regex(const std::string& pattern) {
  std::string out;
  for (size_t i = 0; i < pattern.size(); ++i) {
    const char c = pattern[i];
    if (c == '%') {
      size_t j = i + 1;
      while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) ++j;
      if (j < pattern.size() && pattern[j] == 'd') {
        out += "[0-9]+";
        i = j;
        continue;
      }
    }
    if (std::string("\\^$.|?*+()[]{}").find(c) != std::string::npos) out += '\\';
    out += c;
  }
  return std::regex(out);
}

}  // namespace

std::vector<OutputPath> run_outputs(const Settings& s) {
  std::vector<OutputPath> out;
  if (!s.output.empty() && s.output != "-") out.push_back({s.output, "-o"});
  if (!s.report.empty()) {
    out.push_back({s.report, "--report"});
    out.push_back({fs::path(s.report).replace_extension(".json").string(), "--report's JSON summary"});
    out.push_back({fs::path(s.report).replace_extension(".png").string(), "--report's chart"});
  }
  if (!s.checkpoint.empty() && (s.checkpoint_every > 0 || s.resume)) out.push_back({s.checkpoint, "--checkpoint"});
  if (!s.state_exr.empty()) out.push_back({s.state_exr, "--state-exr"});
  if (!s.progress_file.empty()) out.push_back({s.progress_file, "--progress-file"});
  return out;
}

void check_outputs(const std::vector<OutputPath>& outputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const bool pattern_i = io::is_printf_pattern(outputs[i].path);
    if (!pattern_i) io::check_not_input(outputs[i].path);
    for (size_t j = i + 1; j < outputs.size(); ++j) {
      const bool pattern_j = io::is_printf_pattern(outputs[j].path);
      bool same = normal(outputs[i].path) == normal(outputs[j].path);
      if (!same && pattern_i != pattern_j) {
        const std::string& pattern = pattern_i ? outputs[i].path : outputs[j].path;
        const std::string& file = pattern_i ? outputs[j].path : outputs[i].path;
        same = std::regex_match(normal(file), pattern_regex(normal(pattern)));
      }
      if (same)
        throw UsageError(outputs[j].role + " (" + outputs[j].path + ") would write the same file as " +
                         outputs[i].role + " (" + outputs[i].path + "); name them apart");
    }
  }
}

void refuse_existing(const std::vector<OutputPath>& outputs, std::int64_t first_frame, std::int64_t end_frame) {
  const auto refuse = [](const std::string& path, const std::string& role) {
    throw OutputError(path + " (" + role + ") exists; pass -y (--overwrite) to replace it");
  };
  for (const OutputPath& o : outputs) {
    if (!io::is_printf_pattern(o.path)) {
      if (fs::exists(o.path)) refuse(o.path, o.role);
      continue;
    }
    if (end_frame > first_frame) {
      for (std::int64_t k = first_frame; k < end_frame; ++k)
        if (fs::exists(io::format_pattern(o.path, k))) refuse(io::format_pattern(o.path, k), o.role);
      continue;
    }
    const fs::path folder = fs::path(normal(o.path)).parent_path();
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) continue;
    const std::regex frames = pattern_regex(normal(o.path));
    for (const fs::directory_entry& e : fs::directory_iterator(folder, ec))
      if (std::regex_match(normal(e.path().string()), frames))
        refuse(e.path().string(), o.role);
  }
}

void require_extension(const std::string& path, const std::vector<std::string>& extensions, const std::string& role) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (std::find(extensions.begin(), extensions.end(), ext) != extensions.end()) return;
  std::string list;
  for (const std::string& e : extensions) list += (list.empty() ? "" : " or ") + e;
  throw UsageError(role + " '" + path + "': writes " + list + " only; name the file so");
}

}  // namespace eyestream::pipeline
