// libav's text for one of its error codes, for the one-line messages of the
// video reader, writer and joiner.
#pragma once

extern "C" {
#include <libavutil/error.h>
}

#include <string>

namespace eyestream::io {

inline std::string av_error_text(int code) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {0};
  av_strerror(code, buf, sizeof(buf));
  return buf;
}

}  // namespace eyestream::io
