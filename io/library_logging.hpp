// How much the FFmpeg and OpenCV libraries print on stderr.
#pragma once

namespace eyestream::io {

// Nothing, or (verbose) the libraries' informational messages.
void set_library_verbosity(bool verbose);

}  // namespace eyestream::io
