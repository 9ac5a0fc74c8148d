#include "pipeline/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace eyestream::pipeline {

Progress::Progress(std::int64_t total, bool enabled, double every_s)
    : total_(total),
      enabled_(enabled),
      terminal_(::isatty(STDERR_FILENO)),
      every_s_(every_s),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

double Progress::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::frame_done() {
  ++done_;
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double secs = elapsed_s(), fps = secs > 0 ? done_ / secs : 0.0;
  if (!terminal_) {  // a plain line now and then, for logs
    if (std::chrono::duration<double>(now - last_draw_).count() < every_s_) return;
    last_draw_ = now;
    std::fprintf(stderr, "eyestream: %lld", (long long)done_);
    if (total_ > 0) std::fprintf(stderr, "/%lld", (long long)total_);
    std::fprintf(stderr, " frames, %.2f fps", fps);
    if (total_ > 0 && fps > 0) std::fprintf(stderr, ", ETA %.0f s", (total_ - done_) / fps);
    std::fprintf(stderr, "\n");
    return;
  }
  if (done_ != total_ && now - last_draw_ < std::chrono::milliseconds(200)) return;
  last_draw_ = now;
  if (total_ > 0) {
    const int width = 30, filled = int(width * done_ / total_);
    const double eta = fps > 0 ? (total_ - done_) / fps : 0.0;
    std::fprintf(stderr, "\r[%.*s%*s] %lld/%lld frames  %.1f fps  ETA %.0f s ", filled,
                 "##############################", width - filled, "", (long long)done_, (long long)total_, fps, eta);
  } else {
    std::fprintf(stderr, "\r%lld frames  %.1f fps ", (long long)done_, fps);
  }
  std::fflush(stderr);
}

void Progress::finish() {
  if (enabled_ && terminal_) std::fprintf(stderr, "\n");
}

}  // namespace eyestream::pipeline
