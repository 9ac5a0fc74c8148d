#include "tests/counting_malloc.hpp"

#include <atomic>
#include <cerrno>
#include <cstdlib>

extern "C" {
void* __libc_malloc(size_t);
void* __libc_calloc(size_t, size_t);
void* __libc_realloc(void*, size_t);
void* __libc_memalign(size_t, size_t);
void __libc_free(void*);
}

namespace {

std::atomic<bool> counting{false};
std::atomic<long long> calls{0}, large_calls{0}, bytes{0};
std::atomic<size_t> largest{0};

void count(size_t n) {
  if (!counting.load(std::memory_order_relaxed)) return;
  calls.fetch_add(1, std::memory_order_relaxed);
  bytes.fetch_add(static_cast<long long>(n), std::memory_order_relaxed);
  if (n >= eyestream::test::kLargeAllocation) large_calls.fetch_add(1, std::memory_order_relaxed);
  size_t seen = largest.load(std::memory_order_relaxed);
  while (n > seen && !largest.compare_exchange_weak(seen, n, std::memory_order_relaxed)) {
  }
}

}  // namespace

extern "C" {

void* malloc(size_t n) {
  count(n);
  return __libc_malloc(n);
}

void* calloc(size_t count_of, size_t size) {
  count(count_of * size);
  return __libc_calloc(count_of, size);
}

void* realloc(void* p, size_t n) {
  count(n);
  return __libc_realloc(p, n);
}

void free(void* p) { __libc_free(p); }

void* memalign(size_t alignment, size_t n) {
  count(n);
  return __libc_memalign(alignment, n);
}

void* aligned_alloc(size_t alignment, size_t n) {
  count(n);
  return __libc_memalign(alignment, n);
}

int posix_memalign(void** out, size_t alignment, size_t n) {
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  count(n);
  void* p = __libc_memalign(alignment, n);
  if (!p) return ENOMEM;
  *out = p;
  return 0;
}

}  // extern "C"

namespace eyestream::test {

void start_counting_allocations() {
  calls = 0, large_calls = 0, bytes = 0, largest = 0;
  counting = true;
}

AllocationCount stop_counting_allocations() {
  counting = false;
  return {calls.load(), large_calls.load(), bytes.load(), largest.load()};
}

}  // namespace eyestream::test
