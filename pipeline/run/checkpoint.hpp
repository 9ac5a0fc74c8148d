// Checkpoints of a run (`--checkpoint FILE --checkpoint-every N`,
// `--resume`): everything the frame loop carries from frame to frame, so a
// killed run continues where its last checkpoint left it and ends with the
// same output bytes as an uninterrupted run.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/frame_source.hpp"
#include "pipeline/eye/eye_simulator.hpp"
#include "pipeline/settings/settings.hpp"

namespace eyestream::pipeline {

struct Checkpoint {
  std::uint64_t identity = 0;  // run_identity() of the run that wrote it
  std::string settings;        // its run_settings(), to name what differs
  std::int64_t next_frame = 0;  // the first frame not yet written
  nlohmann::json report;        // ReportWriter::save(), or null
  std::vector<EyeMemory> panels;
};

// Every setting that changes the output (all run parameters but threads,
// progress, verbosity and the checkpoint options), the input, gaze, output
// paths, and the input's size and length, one "name=value" line each.
std::string run_settings(const Settings& settings, const io::SourceInfo& source);
// Its hash (FNV-1a).
std::uint64_t run_identity(const std::string& run_settings);

// Empty when `c` was written by a run with these settings; else the message
// that refuses it, naming the file and the first setting that differs.
std::string checkpoint_mismatch(const std::string& path, const Checkpoint& c, const std::string& run_settings);

// Written under a temporary name and renamed, so a crash leaves the last
// complete checkpoint. Errors: OutputError naming the file.
void write_checkpoint(const std::string& path, const Checkpoint& checkpoint);

// The file starts with a magic line and a checksum of the rest. InputError
// naming the file when it is missing, truncated, corrupt (checksum), or not
// a checkpoint (its sizes and counts are checked before anything is
// allocated from them).
Checkpoint read_checkpoint(const std::string& path);

}  // namespace eyestream::pipeline
