// How large a frame this machine can filter: the default of --max-pixels.
#pragma once

#include <cstdint>

namespace eyestream::io {

// Peak memory per frame pixel, measured: an 8192x4320 frame peaked at
// 9.7 GB in `balanced` (275 bytes per pixel); `reference` keeps double
// precision and a finer retina grid, so 400 is taken.
inline constexpr std::int64_t kBytesPerPixel = 400;

// The machine's physical memory over kBytesPerPixel, within 1e6 and 4e8
// pixels (64 million on a 24 GiB machine: 8K frames fit).
std::int64_t default_max_pixels();

}  // namespace eyestream::io
