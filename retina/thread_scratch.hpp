// Working memory a parallel loop's body needs for a row or a stripe (a ring
// of blurred rows, a widened row), kept per thread and per use so the frame
// loop asks nothing of the allocator once it has run a frame: the worker
// threads live as long as the program, and each keeps the largest size it
// was asked for. What the memory held before is not cleared; a caller
// writes before it reads.
#pragma once

#include <cstddef>
#include <vector>

namespace eyestream::retina {

// `count` elements of T, this thread's own for the use `Tag` (any type
// naming the caller, so two uses on one thread never share).
template <typename Tag, typename T>
T* thread_scratch(std::size_t count) {
  static thread_local std::vector<T> buffer;
  if (buffer.size() < count) buffer.resize(count);
  return buffer.data();
}

}  // namespace eyestream::retina
