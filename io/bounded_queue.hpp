// A first-in first-out queue of at most `capacity` items between one
// producer thread and one consumer thread; either side can close it, which
// wakes the other. Used to run decoding and encoding beside the eye.
#pragma once

#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>

namespace eyestream::io {

template <typename T>
class BoundedQueue {
 public:
  explicit BoundedQueue(size_t capacity) : capacity_(capacity) {}

  // Waits for room; false (and `item` dropped) once the queue is closed.
  bool push(T item) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return closed_ || items_.size() < capacity_; });
    if (closed_) return false;
    items_.push_back(std::move(item));
    changed_.notify_all();
    return true;
  }

  // Waits for room without adding anything: a producer that waits before
  // making its next item holds none while the queue is full. False once
  // the queue is closed.
  bool wait_for_room() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return closed_ || items_.size() < capacity_; });
    return !closed_;
  }

  // Waits for an item; nothing once the queue is closed and empty.
  std::optional<T> pop() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return closed_ || !items_.empty(); });
    if (items_.empty()) return std::nullopt;
    T item = std::move(items_.front());
    items_.pop_front();
    ++taken_;
    changed_.notify_all();
    return item;
  }

  // The consumer says it has finished with every item it took.
  void done_with_taken() {
    std::lock_guard<std::mutex> lock(mutex_);
    finished_ = taken_;
    changed_.notify_all();
  }

  // Waits until the consumer has taken and finished every item pushed so
  // far (or the queue is closed).
  void drain() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return closed_ || (items_.empty() && finished_ == taken_); });
  }

  void close() {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
    changed_.notify_all();
  }

 private:
  const size_t capacity_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<T> items_;
  size_t taken_ = 0, finished_ = 0;
  bool closed_ = false;
};

}  // namespace eyestream::io
