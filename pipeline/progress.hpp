// Progress on stderr while frames stream: a bar when stderr is a terminal
// (frames done, frames/s, ETA); otherwise (CI, Slurm, nohup) a plain line
// every `every_s` seconds.
#pragma once

#include <chrono>
#include <cstdint>

namespace eyestream::pipeline {

class Progress {
 public:
  // total < 0: unknown length (no ETA).
  Progress(std::int64_t total, bool enabled, double every_s = 10.0);
  void frame_done();
  void finish();
  double elapsed_s() const;

 private:
  std::int64_t total_, done_ = 0;
  bool enabled_, terminal_;
  double every_s_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace eyestream::pipeline
