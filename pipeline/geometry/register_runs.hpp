// Bilinear shares added to a block of sums run by run, as the fixed splat
// (onto the angle plane) and the bilinear splat (onto the retina's grid)
// add them: the four sums a pixel adds to are held in registers while the
// next pixels land on the same pair of rows, in the same column or one
// column on (most do); the left column's two sums are stored as the
// footprint moves one column right, and the new right column's read; any
// other step stores the four and starts afresh. Each sum still takes its
// terms in the pixels' order, starting from what the block held, with no
// store and reload between them: the same bytes as adding every share to
// memory (docs/performance.md).
#pragma once

#include <cstddef>

#include "retina/pixel_vector.hpp"

namespace eyestream::pipeline {

// Pixels [x, end): shares(x, i0, j0, tl, tr, bl, br) gives pixel x's
// footprint (its top-left cell at column i0, row j0) and its four shares,
// or false when the pixel adds nothing. `sums` is the block's first row
// r0 - 1 (a border row above the block, and one below it), its cells
// column -1 (a border column each way) on, `stride` cells a row. Inlined
// into its callers, so it runs at their instruction set
// (retina/vector_clones.hpp).
template <typename Shares>
inline void add_in_runs(const Shares& shares, int x, int end, retina::PixelVector* sums, int stride, int r0) {
  using Sum = retina::PixelVector;
  while (x < end) {
    int i0, j0;
    Sum tl, tr, bl, br;
    if (!shares(x, i0, j0, tl, tr, bl, br)) {
      ++x;
      continue;
    }
    Sum* s = &sums[size_t(j0 - r0 + 1) * size_t(stride) + size_t(i0 + 1)];
    Sum t0 = s[0] + tl, t1 = s[1] + tr, b0 = s[stride] + bl, b1 = s[stride + 1] + br;
    const int row = j0;
    int column = i0;
    for (++x; x < end; ++x) {
      if (!shares(x, i0, j0, tl, tr, bl, br) || j0 != row || (i0 != column && i0 != column + 1)) break;
      if (i0 == column) {
        t0 += tl;
        t1 += tr;
        b0 += bl;
        b1 += br;
        continue;
      }
      s[0] = t0;
      s[stride] = b0;
      ++s;
      column = i0;
      t0 = t1 + tl;
      b0 = b1 + bl;
      t1 = s[1] + tr;
      b1 = s[stride + 1] + br;
    }
    s[0] = t0;
    s[1] = t1;
    s[stride] = b0;
    s[stride + 1] = b1;
  }
}

}  // namespace eyestream::pipeline
