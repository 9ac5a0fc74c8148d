// eyestream's exit codes, one per class of failure.
#pragma once

namespace eyestream::pipeline {

enum ExitCode : int {
  kExitOk = 0,
  kExitUsage = 2,     // unknown option, bad value (UsageError, command-line parse errors)
  kExitInput = 3,     // unreadable or malformed input (InputError)
  kExitOutput = 4,    // output cannot be written (OutputError)
  kExitInternal = 5,  // anything else: a bug
};

}  // namespace eyestream::pipeline
