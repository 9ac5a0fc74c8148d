// The streaming frame loop behind `eyestream run`.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "pipeline/settings/settings.hpp"

namespace eyestream::pipeline {

struct RunSummary {
  std::int64_t frames = 0;
  double wall_s = 0.0;
  std::int64_t nonfinite_pixels = 0;
  double final_adaptation_log = 0.0;
  std::string output;
  int interrupted_by = 0;  // the signal that stopped the run early (interrupts.hpp), or 0
  std::string gaze;        // what the gaze log held (gaze_summary.hpp), when there was one
  std::string checkpoint;  // the checkpoint an interrupted run wrote, or ""
  std::string one_line() const;  // with the gaze log's line before it
};

// A run stopped by a signal before it had written anything: nothing is kept.
struct Interrupted : std::runtime_error {
  explicit Interrupted(int sig);
  int signal;
};

// Reads the input frame by frame (memory does not grow with length), steps
// the eye through each frame's interval with the gaze samples inside it,
// and writes the output; the output appears only when complete. Frame k's
// interval ends at frame k+1's time (one frame of look-ahead); the last
// frame's lasts 1/fps. Errors are UsageError, InputError or OutputError.
RunSummary run(const Settings& settings);

// The plan `run` would follow, as text, reading only the first frame.
std::string describe_run(const Settings& settings);

}  // namespace eyestream::pipeline
