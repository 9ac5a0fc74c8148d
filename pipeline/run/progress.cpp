#include "pipeline/run/progress.hpp"

#include <unistd.h>

#include <cstdio>

#include "io/error.hpp"

namespace eyestream::pipeline {

Progress::Progress(std::int64_t total, bool enabled, double every_s, const std::string& file)
    : total_(total),
      enabled_(enabled),
      terminal_(::isatty(STDERR_FILENO)),
      every_s_(every_s),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_),
      last_block_(start_) {
  if (file.empty()) return;
  file_ = std::fopen(file.c_str(), "w");
  if (!file_) throw OutputError(file + ": cannot write the progress file (--progress-file)");
}

Progress::~Progress() {
  if (file_) std::fclose(file_);
}

void Progress::write_block(const char* state) {
  const double secs = elapsed_s(), fps = secs > 0 ? done_ / secs : 0.0;
  std::fprintf(file_, "frame=%lld\ntotal_frames=%lld\nfps=%.3f\nelapsed_s=%.3f\n", (long long)done_,
               (long long)total_, fps, secs);
  if (total_ > 0 && fps > 0) std::fprintf(file_, "eta_s=%.1f\n", (total_ - done_) / fps);
  std::fprintf(file_, "progress=%s\n", state);
  std::fflush(file_);
}

double Progress::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::frame_done() {
  ++done_;
  const auto now = std::chrono::steady_clock::now();
  if (file_ && now - last_block_ >= std::chrono::milliseconds(500)) {
    last_block_ = now;
    write_block("continue");
  }
  if (!enabled_) return;
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
  if (file_) write_block("end");
  if (enabled_ && terminal_) std::fprintf(stderr, "\n");
}

}  // namespace eyestream::pipeline
