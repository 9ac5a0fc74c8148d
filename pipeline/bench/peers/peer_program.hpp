// Running another program for `eyestream bench --peers`: where it is on
// PATH, and one run of a shell command line, timed, with its output.
#pragma once

#include <string>

namespace eyestream::pipeline {

// The first executable regular file called `name` in the folders of PATH, or ""
// when there is none (the peer is not installed).
std::string find_on_path(const std::string& name);

struct ProgramRun {
  int exit_code = -1;     // -1 when it did not exit normally
  std::string output;     // its standard output and error together
  double wall_ms = 0.0;   // from start to exit
};

// Runs `command` with /bin/sh (its standard input from /dev/null unless
// the command redirects it) and waits for it, for at most 30 minutes
// (coreutils' timeout; exit code 124 then). `output` keeps its last 64 KiB
// at least.
ProgramRun run_program(const std::string& command);

// `text` quoted for /bin/sh.
std::string shell_quoted(const std::string& text);

}  // namespace eyestream::pipeline
