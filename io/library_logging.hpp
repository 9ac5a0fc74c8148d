// How much the FFmpeg libraries print on stderr.
#pragma once

namespace eyestream::io {

// Errors only, or (verbose) the libraries' informational messages too.
void set_library_verbosity(bool verbose);

}  // namespace eyestream::io
