#include "pipeline/eye/frame_buffer_pool.hpp"

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <map>
#include <mutex>
#include <opencv2/core.hpp>
#include <vector>

namespace eyestream::pipeline {

namespace {

constexpr size_t kPooledFrom = 64 * 1024;  // smaller buffers: malloc reuses them well already
constexpr size_t kAlignment = 64;           // as OpenCV's own allocator
// Trims (frames) a pooled buffer may sit unused before it is freed, about
// a second at 30 frames/s: a stage that skips frames, or a frame that needs
// a few more buffers than the last ones did, finds them still there (with
// 2, the allocation test saw image-sized blocks taken from the system
// again every few frames).
constexpr unsigned long kIdleTrims = 30;

// The size a buffer of `bytes` is given: rounded up to one of eight steps
// per power of two (at most 12.5 % more), so buffers whose size follows the
// gaze a little (a region of the retina, a near field's box) share a step.
size_t size_step(size_t bytes) {
  size_t power = 1;
  while (power <= bytes / 2) power *= 2;
  const size_t step = std::max<size_t>(power / 8, kAlignment);
  return (bytes + step - 1) / step * step;
}

// A cv::MatAllocator that pools freed buffers by size step. The loop's
// sizes repeat frame after frame, so the pool holds about the working set
// of the last frames; trim() frees what no frame has taken for a while.
class FrameBufferPool final : public cv::MatAllocator {
 public:
  cv::UMatData* allocate(int dims, const int* sizes, int type, void* data0, size_t* step, cv::AccessFlag,
                         cv::UMatUsageFlags) const override {
    size_t total = CV_ELEM_SIZE(type);
    for (int i = dims - 1; i >= 0; --i) {
      if (step) {
        if (data0 && step[i] != cv::Mat::AUTO_STEP) {
          CV_Assert(total <= step[i]);
          total = step[i];
        } else {
          step[i] = total;
        }
      }
      total *= size_t(sizes[i]);
    }
    auto* u = new cv::UMatData(this);
    u->data = u->origdata = data0 ? static_cast<uchar*>(data0) : take(total);
    u->size = total;
    if (data0) u->flags |= cv::UMatData::USER_ALLOCATED;
    return u;
  }

  bool allocate(cv::UMatData* u, cv::AccessFlag, cv::UMatUsageFlags) const override { return u != nullptr; }

  void deallocate(cv::UMatData* u) const override {
    if (!u) return;
    CV_Assert(u->urefcount == 0 && u->refcount == 0);
    if (!(u->flags & cv::UMatData::USER_ALLOCATED)) give_back(u->origdata, u->size);
    delete u;
  }

  size_t pooled() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return pooled_;
  }

 private:
  uchar* take(size_t bytes) const {
    if (bytes >= kPooledFrom) {
      bytes = size_step(bytes);
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = free_.find(bytes);
      if (it != free_.end() && !it->second.empty()) {
        void* p = it->second.back().block;
        it->second.pop_back();
        pooled_ -= bytes;
        return static_cast<uchar*>(p);
      }
    }
    void* p = nullptr;
    if (posix_memalign(&p, kAlignment, bytes == 0 ? kAlignment : bytes) != 0) throw std::bad_alloc();
    return static_cast<uchar*>(p);
  }

  void give_back(void* p, size_t bytes) const {
    if (bytes < kPooledFrom) {
      std::free(p);
      return;
    }
    bytes = size_step(bytes);
    std::lock_guard<std::mutex> lock(mutex_);
    free_[bytes].push_back({p, generation_});
    pooled_ += bytes;
  }

 public:
  // Frees the buffers no frame has taken through the last `idle_trims`
  // trims (0: every buffer held), outside the lock.
  void trim(unsigned long idle_trims) const {
    std::vector<void*> freed;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (auto it = free_.begin(); it != free_.end();) {
        std::vector<Idle>& idle = it->second;
        // Taken from the back, so the longest idle are at the front.
        size_t n = 0;
        while (n < idle.size() && idle[n].since + idle_trims <= generation_) freed.push_back(idle[n++].block);
        pooled_ -= n * it->first;
        idle.erase(idle.begin(), idle.begin() + long(n));
        it = idle.empty() ? free_.erase(it) : std::next(it);
      }
      ++generation_;
    }
    for (void* p : freed) std::free(p);
  }

 private:

  mutable std::mutex mutex_;
  struct Idle {
    void* block;
    unsigned long since;  // the generation it was given back in
  };
  mutable std::map<size_t, std::vector<Idle>> free_;
  mutable unsigned long generation_ = 0;  // trims so far
  mutable size_t pooled_ = 0;
};

// Never destroyed: Mats released during static destruction still find it.
FrameBufferPool& pool() {
  static auto* p = new FrameBufferPool;
  return *p;
}

}  // namespace

void reuse_frame_buffers() {
  static std::once_flag once;
  std::call_once(once, [] { cv::Mat::setDefaultAllocator(&pool()); });
}

size_t pooled_frame_buffer_bytes() { return pool().pooled(); }

void trim_frame_buffers() { pool().trim(kIdleTrims); }

void release_frame_buffers() { pool().trim(0); }

}  // namespace eyestream::pipeline
