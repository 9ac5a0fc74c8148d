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
#include "pipeline/eye_simulator.hpp"
#include "pipeline/settings.hpp"

namespace eyestream::pipeline {

struct Checkpoint {
  std::uint64_t identity = 0;  // run_identity() of the run that wrote it
  std::int64_t next_frame = 0;  // the first frame not yet written
  nlohmann::json report;        // ReportWriter::save(), or null
  std::vector<EyeMemory> panels;
};

// A hash (FNV-1a) of every setting that changes the output (all run
// parameters but threads, progress, verbosity and the checkpoint options),
// the input, gaze, output paths, and the input's size and length.
std::uint64_t run_identity(const Settings& settings, const io::SourceInfo& source);

// Written under a temporary name and renamed, so a crash leaves the last
// complete checkpoint. Errors: OutputError naming the file.
void write_checkpoint(const std::string& path, const Checkpoint& checkpoint);

// InputError naming the file when it is missing, truncated or not a checkpoint.
Checkpoint read_checkpoint(const std::string& path);

}  // namespace eyestream::pipeline
