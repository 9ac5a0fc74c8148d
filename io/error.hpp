// Error classes raised by eyestream's modules. The program maps each class
// to its own exit code (see pipeline/run/exit_codes.hpp); the message is one line
// that names the culprit (file and frame, gaze line, or parameter).
#pragma once

#include <stdexcept>
#include <string>

namespace eyestream {

// The user asked for something invalid: unknown option, out-of-range value.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An input (frame, video, gaze log, config) cannot be read or is malformed.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An output cannot be created, written or finalised.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace eyestream
