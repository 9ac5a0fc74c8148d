#include "io/frame_sequence.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "io/error.hpp"

namespace eyestream::io {
namespace fs = std::filesystem;

namespace {

// Splits "dir/name_%05d.exr" into prefix "name_", width 5, suffix ".exr".
struct PatternParts {
  std::string prefix, suffix;
  int width = 0;
  bool zero_pad = false;
};

// Finds one printf integer conversion "%d", "%Nd" or "%0Nd" in `name`.
bool split_pattern(const std::string& name, PatternParts& out) {
  for (size_t i = name.find('%'); i != std::string::npos; i = name.find('%', i + 1)) {
    size_t j = i + 1;
    const bool zero = j < name.size() && name[j] == '0';
    if (zero) ++j;
    const size_t digits_begin = j;
    while (j < name.size() && std::isdigit(static_cast<unsigned char>(name[j]))) ++j;
    if (j >= name.size() || name[j] != 'd' || j - digits_begin > 2) continue;
    out.prefix = name.substr(0, i);
    out.suffix = name.substr(j + 1);
    out.zero_pad = zero;
    out.width = j > digits_begin ? std::stoi(name.substr(digits_begin, j - digits_begin)) : 0;
    return out.suffix.find('%') == std::string::npos && out.prefix.find('%') == std::string::npos;
  }
  return false;
}

bool has_extension(const fs::path& p, const std::vector<std::string>& exts) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return std::find(exts.begin(), exts.end(), e) != exts.end();
}

std::vector<SequenceEntry> list_pattern(const std::string& pattern, bool skip_missing, const std::string& gap_hint) {
  fs::path p(pattern);
  fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  PatternParts parts;
  split_pattern(p.filename().string(), parts);
  std::vector<std::int64_t> numbers;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::string name = it->path().filename().string();
    if (name.size() <= parts.prefix.size() + parts.suffix.size()) continue;
    if (name.compare(0, parts.prefix.size(), parts.prefix) != 0) continue;
    if (name.compare(name.size() - parts.suffix.size(), parts.suffix.size(), parts.suffix) != 0) continue;
    std::string digits = name.substr(parts.prefix.size(), name.size() - parts.prefix.size() - parts.suffix.size());
    if (digits.empty() || digits.size() > 12 ||
        !std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); }))
      continue;
    std::int64_t n = std::stoll(digits);
    if (format_pattern(pattern, n) == (p.parent_path() / name).string()) numbers.push_back(n);
  }
  if (numbers.empty()) throw InputError(pattern + ": no frame matches this pattern");
  std::sort(numbers.begin(), numbers.end());
  std::vector<SequenceEntry> out;
  for (size_t i = 0; i < numbers.size(); ++i) {
    if (i > 0 && numbers[i] != numbers[i - 1] + 1 && !skip_missing)
      throw InputError(format_pattern(pattern, numbers[i - 1] + 1) +
                       ": missing frame in the sequence (" + gap_hint + ")");
    out.push_back({format_pattern(pattern, numbers[i]), numbers[i]});
  }
  return out;
}

}  // namespace

bool is_printf_pattern(const std::string& pattern) {
  PatternParts parts;
  return split_pattern(fs::path(pattern).filename().string(), parts);
}

std::string format_pattern(const std::string& pattern, std::int64_t number) {
  fs::path p(pattern);
  PatternParts parts;
  if (!split_pattern(p.filename().string(), parts)) return pattern;
  std::string digits = std::to_string(number);
  if (int(digits.size()) < parts.width)
    digits.insert(0, size_t(parts.width) - digits.size(), parts.zero_pad ? '0' : ' ');
  return (p.parent_path() / (parts.prefix + digits + parts.suffix)).string();
}

std::vector<SequenceEntry> list_sequence(const std::string& input, const std::vector<std::string>& extensions,
                                         bool skip_missing, const std::string& gap_hint) {
  if (is_printf_pattern(input)) return list_pattern(input, skip_missing, gap_hint);
  std::error_code ec;
  if (fs::is_directory(input, ec)) {
    std::vector<std::string> names;
    for (fs::directory_iterator it(input, ec), end; !ec && it != end; it.increment(ec))
      if (it->is_regular_file() && has_extension(it->path(), extensions)) names.push_back(it->path().string());
    if (names.empty()) throw InputError(input + ": folder holds no frame files");
    std::sort(names.begin(), names.end());
    // Numbered files (frame_00010.exr ...) keep their numbers, as a pattern
    // would give them, and a gap is refused as a pattern's is (or skipped);
    // names without numbers, or two with one number, go by their position.
    std::vector<SequenceEntry> out;
    for (size_t i = 0; i < names.size(); ++i) {
      const std::string stem = fs::path(names[i]).stem().string();
      const size_t digits = stem.find_last_not_of("0123456789") + 1;  // npos + 1 == 0: all digits
      const size_t count = stem.size() - digits;
      if (count == 0 || count > 12) {
        out.clear();
        break;
      }
      out.push_back({names[i], std::stoll(stem.substr(digits))});
    }
    std::sort(out.begin(), out.end(), [](const SequenceEntry& a, const SequenceEntry& b) { return a.number < b.number; });
    for (size_t i = 1; i < out.size(); ++i)
      if (out[i].number == out[i - 1].number) {
        out.clear();
        break;
      }
    for (size_t i = 1; i < out.size(); ++i)
      if (out[i].number != out[i - 1].number + 1 && !skip_missing)
        throw InputError(out[i - 1].path + " is followed by " + out[i].path + ": missing frame in the sequence (" +
                         gap_hint + ")");
    if (!out.empty()) return out;
    for (size_t i = 0; i < names.size(); ++i) out.push_back({names[i], std::int64_t(i)});
    return out;
  }
  if (!fs::is_regular_file(input, ec)) throw InputError(input + ": no such file, folder or frame pattern");
  return {{input, 0}};
}

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

double sequence_time(const std::vector<SequenceEntry>& entries, size_t i, double frames_per_second) {
  return double(entries[i].number - entries.front().number) / frames_per_second;
}

}  // namespace eyestream::io
