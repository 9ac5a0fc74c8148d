#include "io/memory_guard.hpp"

#include <unistd.h>

#include <algorithm>

namespace eyestream::io {

std::int64_t default_max_pixels() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 400'000'000;
  const std::int64_t bytes = std::int64_t(pages) * std::int64_t(page);
  return std::clamp<std::int64_t>(bytes / kBytesPerPixel, 1'000'000, 400'000'000);
}

}  // namespace eyestream::io
