// Progress on stderr while frames stream: a bar when stderr is a terminal
// (frames done, frames/s, ETA); otherwise (CI, Slurm, nohup) a plain line
// every `every_s` seconds. For programs, --progress-file: blocks of
// key=value lines, as ffmpeg's -progress writes them, every half second
// and at the end:
//   frame=120  total_frames=600  fps=3.41  elapsed_s=35.2  eta_s=140.8
//   progress=continue (progress=end once every output is in place)
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace eyestream::pipeline {

class Progress {
 public:
  // total < 0: unknown length (no ETA).
  // `file` (may be empty: none) is truncated now and written as frames go.
  Progress(std::int64_t total, bool enabled, double every_s = 10.0, const std::string& file = "");
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void frame_done();
  void finish();
  double elapsed_s() const;

 private:
  std::int64_t total_, done_ = 0;
  bool enabled_, terminal_;
  double every_s_;
  std::chrono::steady_clock::time_point start_, last_draw_, last_block_;
  std::FILE* file_ = nullptr;
  void write_block(const char* state);
};

}  // namespace eyestream::pipeline
