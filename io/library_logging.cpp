#include "io/library_logging.hpp"

extern "C" {
#include <libavutil/log.h>
}

namespace eyestream::io {

void set_library_verbosity(bool verbose) { av_log_set_level(verbose ? AV_LOG_INFO : AV_LOG_ERROR); }

}  // namespace eyestream::io
