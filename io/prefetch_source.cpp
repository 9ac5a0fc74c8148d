#include "io/prefetch_source.hpp"

namespace eyestream::io {

PrefetchSource::PrefetchSource(std::unique_ptr<FrameSource> source, size_t depth, std::int64_t last_index)
    : source_(std::move(source)), queue_(depth) {
  reader_ = std::thread([this, last_index] {
    bool past_last = false;
    for (;;) {
      if (!queue_.wait_for_room()) return;  // nothing decoded is held while the queue is full
      Item item;
      try {
        if (!past_last) item.frame = source_->next();  // else the end
      } catch (...) {
        item.error = std::current_exception();
      }
      const bool last = !item.frame || item.error;
      past_last = item.frame && last_index >= 0 && item.frame->index >= last_index;
      if (!queue_.push(std::move(item)) || last) return;
    }
  });
}

PrefetchSource::~PrefetchSource() {
  queue_.close();
  reader_.join();
}

std::optional<SceneFrame> PrefetchSource::next() {
  if (ended_) return std::nullopt;
  std::optional<Item> item = queue_.pop();
  if (!item || !item->frame) ended_ = true;
  if (item && item->error) std::rethrow_exception(item->error);
  return item ? std::move(item->frame) : std::nullopt;
}

}  // namespace eyestream::io
