// `eyestream chunks`: splits a long input into chunks that separate
// processes or hosts can filter at once. The eye forgets its past within
// seconds (adaptation and photopigment recovery rates), so each chunk
// first processes a pre-roll of the frames before it without writing them
// (run --start-frame/--end-frame/--preroll).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace eyestream::pipeline {

struct ChunkRequest {
  std::string program = "eyestream";  // as the commands should call it
  std::string input, output;          // output: a video pattern with %d (chunk number) or a frame pattern
  std::int64_t chunk_frames = 0;
  double preroll_s = 10.0;  // measured: the pre-roll table in docs/usage.md
  std::vector<std::string> run_options;  // passed to every chunk's run
};

struct Chunk {
  std::int64_t start = 0, end = 0;  // frames written: [start, end)
  std::string output;
  std::string command;  // one shell command line
};

// The chunks of `frame_count` frames. Video outputs (.mp4, .mkv) need a
// printf %d in `output` for the chunk number; PNG and EXR frame patterns
// are shared (frames are named by their position in the input, so the
// chunks' frames together are the whole sequence). UsageError otherwise.
std::vector<Chunk> plan_chunks(const ChunkRequest& request, std::int64_t frame_count);

// Quotes an argument for a POSIX shell when it needs it.
std::string shell_quote(const std::string& arg);

}  // namespace eyestream::pipeline
