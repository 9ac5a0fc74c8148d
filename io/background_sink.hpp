// Encodes and writes frames on a thread of its own while the eye works on
// the next one. Frames are written in order, exactly as by the wrapped
// sink; an error writing a frame is thrown by the next call (write, commit
// or finish), and nothing more is written after it. Destroyed without
// finish(), it stops the thread and the wrapped sink removes what it wrote.
#pragma once

#include <exception>
#include <memory>
#include <mutex>
#include <thread>

#include "io/bounded_queue.hpp"
#include "io/frame_sink.hpp"

namespace eyestream::io {

class BackgroundSink : public FrameSink {
 public:
  // Holds up to `depth` frames waiting to be written.
  BackgroundSink(std::unique_ptr<FrameSink> sink, size_t depth = 2);
  ~BackgroundSink() override;

  SinkNeeds needs() const override { return sink_->needs(); }
  void write(const DisplayFrame& frame) override;
  void finish() override;
  bool commit_so_far() override;

 private:
  void wait_idle();  // every frame so far written; rethrows the writer's error
  std::unique_ptr<FrameSink> sink_;
  BoundedQueue<DisplayFrame> queue_;
  std::mutex error_mutex_;
  std::exception_ptr error_;
  std::thread writer_;
};

}  // namespace eyestream::io
