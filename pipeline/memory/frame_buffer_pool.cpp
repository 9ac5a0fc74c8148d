#include "pipeline/memory/frame_buffer_pool.hpp"

#include "glare/huge_pages.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <map>
#include <mutex>
#include <opencv2/core.hpp>
#include <vector>

namespace eyestream::pipeline {

namespace {

constexpr size_t kPooledFrom = 64 * 1024;  // smaller buffers: malloc reuses them well already
constexpr size_t kAlignment = 64;          // as OpenCV's own allocator
// Buffers of a huge page or more are mapped on huge-page boundaries and
// marked for transparent huge pages: the set-up touches hundreds of MB of
// new buffers, and a fault per 4 KiB page cost a third of a one-frame
// 1080p run's CPU (180 000 faults in `balanced`). Where the system gives
// no huge pages (THP off, or not Linux) they are ordinary mappings. 2 MiB
// is x86-64's huge page (the machines eyestream is built and measured on);
// elsewhere the advice may simply find no whole huge page to act on.
constexpr size_t kHugePage = size_t(2) << 20;
// Under AddressSanitizer every block comes from malloc, which it watches
// (gcc says so with __SANITIZE_ADDRESS__, clang before 17 only through
// __has_feature).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kMapHuge = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kMapHuge = false;
#else
constexpr bool kMapHuge = true;
#endif
#else
constexpr bool kMapHuge = true;
#endif
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

// `bytes` (at least kHugePage) mapped from a huge-page boundary: a mapping
// one huge page longer, its unaligned head and its tail unmapped, the rest
// marked for huge pages. A huge page is taken whole when first touched, so
// the part of a block's last huge page beyond what a frame writes costs
// memory too: about 10 MiB of `balanced`'s 1080p peak (which the FFT
// engine's kernel spectra, written in place since, gave back). Marking
// only the whole huge pages inside each request kept that memory but took
// twice the faults (36 000 against 18 000 in a one-frame run).
void* map_huge(size_t bytes) {
  void* p = mmap(nullptr, bytes + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  const uintptr_t start = reinterpret_cast<uintptr_t>(p), end = start + bytes + kHugePage;
  const uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  static const uintptr_t page = uintptr_t(sysconf(_SC_PAGESIZE));
  const uintptr_t aligned_end = (aligned + bytes + page - 1) / page * page;
  if (aligned > start) munmap(p, aligned - start);
  if (end > aligned_end) munmap(reinterpret_cast<void*>(aligned_end), end - aligned_end);
  glare::prefer_huge_pages(reinterpret_cast<void*>(aligned), bytes);  // the whole huge pages; the tail has none
  return reinterpret_cast<void*>(aligned);
}

// Returns a block of `bytes` (a size step) to the system.
void release(void* p, size_t bytes) {
  if (kMapHuge && bytes >= kHugePage)
    munmap(p, bytes);
  else
    std::free(p);
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
    uchar* data = data0 ? static_cast<uchar*>(data0) : take(total);
    cv::UMatData* u = nullptr;
    try {
      u = new cv::UMatData(this);
    } catch (...) {
      if (!data0) give_back(data, total);
      throw;
    }
    u->data = u->origdata = data;
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

  unsigned long mapped() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return mapped_;
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
    if (kMapHuge && bytes >= kHugePage) {
      void* p = map_huge(bytes);  // a size step, as give_back() sees it
      std::lock_guard<std::mutex> lock(mutex_);
      ++mapped_;
      return static_cast<uchar*>(p);
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
    std::vector<std::pair<void*, size_t>> freed;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (auto it = free_.begin(); it != free_.end();) {
        std::vector<Idle>& idle = it->second;
        // Taken from the back, so the longest idle are at the front.
        size_t n = 0;
        while (n < idle.size() && idle[n].since + idle_trims <= generation_)
          freed.push_back({idle[n++].block, it->first});
        pooled_ -= n * it->first;
        idle.erase(idle.begin(), idle.begin() + long(n));
        it = idle.empty() ? free_.erase(it) : std::next(it);
      }
      ++generation_;
    }
    for (const auto& [p, bytes] : freed) release(p, bytes);
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
  mutable unsigned long mapped_ = 0;  // blocks mapped by map_huge() so far
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

unsigned long frame_buffers_mapped() { return pool().mapped(); }

void trim_frame_buffers() { pool().trim(kIdleTrims); }

void release_frame_buffers() { pool().trim(0); }

}  // namespace eyestream::pipeline
