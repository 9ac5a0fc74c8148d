#include "pipeline/output_paths.hpp"

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

}  // namespace eyestream::pipeline
