#include "io/library_logging.hpp"

#include <opencv2/core/utils/logger.hpp>

extern "C" {
#include <libavutil/log.h>
}

namespace eyestream::io {

// Refusals are eyestream's own one line; the libraries' messages would
// only come before it, so they are silent unless --verbose asks.
void set_library_verbosity(bool verbose) {
  av_log_set_level(verbose ? AV_LOG_INFO : AV_LOG_QUIET);
  cv::utils::logging::setLogLevel(verbose ? cv::utils::logging::LOG_LEVEL_INFO
                                          : cv::utils::logging::LOG_LEVEL_SILENT);
}

}  // namespace eyestream::io
