// Helpers shared by the tests: scratch folders and running the program.
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <map>
#include <string>
#include <vector>

#include "pipeline/settings/plan.hpp"

namespace eyestream::test {

// True in the AddressSanitizer build (CI's second pass, about ten times
// slower): the longest numerical sweeps run a corner of their matrix there
// (every code path, fewer sizes and rates) and the whole of it in release.
#if defined(__SANITIZE_ADDRESS__)
#define EYESTREAM_TEST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define EYESTREAM_TEST_SANITIZED 1
#endif
#endif
#ifdef EYESTREAM_TEST_SANITIZED
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

// A fresh empty folder under the system temp folder, removed on destruction.
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs the eyestream binary with `args` (a shell-quoted string).
CommandResult run_eyestream(const std::string& args);

// The fields of one CSV row (no quoting; empty fields kept).
std::vector<std::string> csv_fields(const std::string& row);

// A CSV file's rows as maps from its header's names to the fields.
std::vector<std::map<std::string, std::string>> csv_rows(const std::string& path);

// Reads a whole file as bytes.
std::string read_bytes(const std::string& path);

// Number of entries in a folder (0 if it does not exist).
int count_entries(const std::filesystem::path& dir);

// The first of the PNG frames 00000.png .. (frames - 1) whose bytes differ
// between folders a and b, or "" when all are the same.
std::string first_differing_png(const std::filesystem::path& a, const std::filesystem::path& b, int frames);

// Channel `name` of an EXR file as OpenEXR's own readPixels gives it,
// converted to float, row by row over the data window: an oracle that
// does not go through the project's reader.
std::vector<float> openexr_channel(const std::string& path, const std::string& name);

// A constant CV_32FC3 frame.
cv::Mat constant_frame(int width, int height, const cv::Vec3f& rgb);

// The plan for `settings` and a width x height source, display-linear output.
pipeline::Plan plan_for(const pipeline::Settings& settings, int width, int height, double fps = 30.0);

}  // namespace eyestream::test
