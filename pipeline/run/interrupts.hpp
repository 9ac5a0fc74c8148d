// Stopping a run cleanly on request: Ctrl-C (SIGINT), SIGTERM (a Slurm time
// limit, `kill`) and SIGHUP. The first signal only sets a flag; the frame
// loop stops after the frame in hand, finishes what it made (a playable
// video of the frames so far, committed image frames, the report, a
// checkpoint when one is configured), removes every temporary, and the
// program exits 128 + the signal (130, 143, 129). A second signal ends the
// process at once. SIGPIPE is ignored: a closed standard output is an
// output error (exit 4), with the same clean-up.
#pragma once

namespace eyestream::pipeline {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handlers
  ~InterruptGuard();  // restores the previous ones
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // The signal received since construction, or 0.
  static int received();
};

// "SIGINT", "SIGTERM" or "SIGHUP".
const char* signal_name(int signal);

}  // namespace eyestream::pipeline
