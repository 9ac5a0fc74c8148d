#include "io/background_sink.hpp"

namespace eyestream::io {

BackgroundSink::BackgroundSink(std::unique_ptr<FrameSink> sink, size_t depth)
    : sink_(std::move(sink)), queue_(depth) {
  writer_ = std::thread([this] {
    while (std::optional<DisplayFrame> frame = queue_.pop()) {
      try {
        sink_->write(*frame);
      } catch (...) {
        {
          std::lock_guard<std::mutex> lock(error_mutex_);
          error_ = std::current_exception();
        }
        queue_.close();  // nothing more is written; the producer hears of it
        return;
      }
      queue_.done_with_taken();
    }
  });
}

BackgroundSink::~BackgroundSink() {
  queue_.close();
  if (writer_.joinable()) writer_.join();
}

void BackgroundSink::write(const DisplayFrame& frame) {
  {
    std::lock_guard<std::mutex> lock(error_mutex_);
    if (error_) std::rethrow_exception(error_);
  }
  if (!queue_.push(frame)) wait_idle();  // closed: only by an error
}

void BackgroundSink::wait_idle() {
  queue_.drain();
  std::lock_guard<std::mutex> lock(error_mutex_);
  if (error_) std::rethrow_exception(error_);
}

bool BackgroundSink::commit_so_far() {
  wait_idle();
  return sink_->commit_so_far();
}

void BackgroundSink::finish() {
  wait_idle();
  queue_.close();
  writer_.join();
  {
    std::lock_guard<std::mutex> lock(error_mutex_);
    if (error_) std::rethrow_exception(error_);
  }
  sink_->finish();
}

}  // namespace eyestream::io
