// Every file a run will write, resolved before the first frame: the video
// or frames, the report's CSV, JSON and chart, the checkpoint and the state
// EXR. Two that coincide, or one that would replace an input, are refused
// before anything is written.
#pragma once

#include <string>
#include <vector>

#include "pipeline/settings.hpp"

namespace eyestream::pipeline {

struct OutputPath {
  std::string path;  // a file, or a printf pattern of numbered frames
  std::string role;  // the option that names it, for messages
};

// The run's outputs, in the order they are described.
std::vector<OutputPath> run_outputs(const Settings& s);

// UsageError naming both options when two outputs are the same file (or a
// file matches the frames' pattern); OutputError when one is an input (the
// inputs must be registered with io::protect_input first).
void check_outputs(const std::vector<OutputPath>& outputs);

}  // namespace eyestream::pipeline
