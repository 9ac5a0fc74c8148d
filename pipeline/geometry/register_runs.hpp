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

// A block's cells: block row j (0 the block's first row, r0; -1 and the
// block's height the border rows) and column i (-1 and the target's
// width the border columns), `stride` cells a row (the width + 2).
inline size_t block_cell(int j, int i, int stride) { return size_t(j + 1) * size_t(stride) + size_t(i + 1); }

// Pixels [x, end): shares(x, i0, j0, tl, tr, bl, br) gives pixel x's
// footprint (its top-left cell at column i0, row j0) and its four shares,
// or false when the pixel adds nothing; `sums` holds the block's cells
// (block_cell), the block's first row being r0. Inlined
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
    Sum* s = &sums[block_cell(j0 - r0, i0, stride)];
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
