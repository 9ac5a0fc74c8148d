#include "pipeline/run/chunk_plan.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "io/error.hpp"
#include "io/frame_sequence.hpp"

namespace eyestream::pipeline {

std::string shell_quote(const std::string& arg) {
  const bool plain = !arg.empty() && std::all_of(arg.begin(), arg.end(), [](unsigned char c) {
    return std::isalnum(c) || std::string("-_./=:,%+@").find(char(c)) != std::string::npos;
  });
  if (plain) return arg;
  std::string q = "'";
  for (char c : arg) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::vector<Chunk> plan_chunks(const ChunkRequest& r, std::int64_t frame_count) {
  if (r.chunk_frames < 1) throw UsageError("--chunk-frames must be at least 1");
  if (frame_count < 1) throw UsageError(r.input + ": the number of frames is unknown; chunks need it");
  const std::string ext = io::lower_extension(r.output);
  const bool video = ext == ".mp4" || ext == ".mkv";
  if (video && !io::is_printf_pattern(r.output))
    throw UsageError("-o " + r.output + ": a chunked video needs a chunk number pattern, e.g. chunk_%03d.mp4");
  if (!video && (ext != ".png" && ext != ".exr"))
    throw UsageError("-o " + r.output + ": chunks write .mp4/.mkv per chunk or a .png/.exr frame pattern");
  char preroll[32];
  std::snprintf(preroll, sizeof(preroll), "%g", r.preroll_s);
  std::vector<Chunk> chunks;
  for (std::int64_t start = 0, k = 0; start < frame_count; start += r.chunk_frames, ++k) {
    Chunk c;
    c.start = start;
    c.end = std::min(frame_count, start + r.chunk_frames);
    c.output = video ? io::format_pattern(r.output, k) : r.output;
    c.command = shell_quote(r.program) + " run -i " + shell_quote(r.input) + " -o " + shell_quote(c.output) +
                " --start-frame " + std::to_string(c.start) + " --end-frame " + std::to_string(c.end) +
                " --preroll " + preroll;
    for (const std::string& a : r.run_options) c.command += " " + shell_quote(a);
    chunks.push_back(c);
  }
  return chunks;
}

}  // namespace eyestream::pipeline
