// Counts the calls into the C allocator (malloc, calloc, realloc,
// posix_memalign, aligned_alloc, memalign, and so operator new, which calls
// malloc) while counting is on. The program that links counting_malloc.cpp
// replaces glibc's allocator entry points with ones that count and then
// call glibc's own (__libc_malloc and the rest): every shared library the
// program loads (OpenCV, FFTW, libstdc++) allocates through them too. Not
// for sanitizer builds, which replace the allocator themselves.
#pragma once

#include <cstddef>

namespace eyestream::test {

struct AllocationCount {
  long long calls = 0;        // every allocation
  long long large_calls = 0;  // those of at least kLargeAllocation bytes
  long long bytes = 0;        // bytes asked for in all
  size_t largest = 0;         // the largest single request
};

// "Large": an image-sized block, above glibc's default mmap threshold
// (128 KiB), whose pages the system maps, faults in and zeroes each time.
constexpr size_t kLargeAllocation = 128 * 1024;

// Starts counting from zero on every thread.
void start_counting_allocations();
// Stops counting and returns what was counted since the start.
AllocationCount stop_counting_allocations();

}  // namespace eyestream::test
