// Every file a run will write, resolved before the first frame: the video
// or frames, the report's CSV, JSON and chart, the checkpoint and the state
// EXR. Two that coincide, or one that would replace an input, are refused
// before anything is written.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pipeline/settings/settings.hpp"

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

// OutputError naming the first output that already exists, and -y:
// existing outputs are replaced only when asked. A frame pattern counts
// the frames first_frame .. end_frame - 1 it will write (so chunks share
// one pattern), or any file it matches when end_frame <= first_frame.
void refuse_existing(const std::vector<OutputPath>& outputs, std::int64_t first_frame = 0,
                     std::int64_t end_frame = -1);

// UsageError when `path` (or the pattern) does not end in one of
// `extensions` (lower case, with the dot): what a command cannot write is
// refused, not written in another format under that name.
void require_extension(const std::string& path, const std::vector<std::string>& extensions, const std::string& role);

}  // namespace eyestream::pipeline
