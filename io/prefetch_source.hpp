// Decodes the next frames on a thread of its own while the eye works on
// the current one. Frames arrive in the same order and with the same
// content as from the wrapped source; an error reading a frame is thrown
// by next() at that frame, as the wrapped source would throw it.
#pragma once

#include <cstdint>

#include <exception>
#include <memory>
#include <thread>

#include "io/bounded_queue.hpp"
#include "io/frame_source.hpp"

namespace eyestream::io {

class PrefetchSource : public FrameSource {
 public:
  // Holds up to `depth` decoded frames that next() has not returned: the
  // reader decodes a frame only once there is room for it. With
  // `last_index` >= 0 it decodes none after the frame of that index (the
  // last a run wants, at --end-frame), and the source ends there.
  PrefetchSource(std::unique_ptr<FrameSource> source, size_t depth = 2, std::int64_t last_index = -1);
  ~PrefetchSource() override;

  const SourceInfo& info() const override { return source_->info(); }
  std::optional<SceneFrame> next() override;
  bool knows_times() const override { return source_->knows_times(); }
  std::optional<double> time_of(std::int64_t index) const override { return source_->time_of(index); }

 private:
  struct Item {
    std::optional<SceneFrame> frame;  // nothing: the end
    std::exception_ptr error;
  };
  std::unique_ptr<FrameSource> source_;
  BoundedQueue<Item> queue_;
  bool ended_ = false;
  std::thread reader_;
};

}  // namespace eyestream::io
