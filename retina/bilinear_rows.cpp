#include "retina/bilinear_rows.hpp"

#include <algorithm>

#include "retina/pixel_vector.hpp"
#include "retina/vector_clones.hpp"

namespace eyestream::retina {

namespace {

EYESTREAM_VECTOR_CLONES
void enlarge_taps(const float* __restrict row, const int* __restrict lo, const int* __restrict hi,
                  const float* __restrict w, float* __restrict out, int n) {
  for (int x = 0; x < n; ++x) out[x] = row[lo[x]] * (1.0f - w[x]) + row[hi[x]] * w[x];
}

// Three channels a pixel, the pixel's three values at once: the same
// products and sum for each channel as a loop over values. The fourth
// lane reads the map's next value and writes the next output pixel's
// first, which that pixel then writes. The taps are in order, so the map
// pixels before the last one read (hi[n - 1]) have a next value in the
// row; the pixels reading that one, and the last output pixel, which has
// no next one, move three floats. (On this project's AMD EPYC machine the
// loop over values, as vector gathers, took twice the time.)
void enlarge_taps3(const float* __restrict row, const int* __restrict lo, const int* __restrict hi,
                   const float* __restrict w, float* __restrict out, int n) {
  if (n <= 0) return;
  const int last = hi[n - 1];
  for (int x = 0; x < n; ++x) {
    const float fx = w[x];
    const bool inside = hi[x] < last;
    const PixelVector a = inside ? four_floats(row + 3 * lo[x]) : three_floats(row + 3 * lo[x]);
    const PixelVector b = inside ? four_floats(row + 3 * hi[x]) : three_floats(row + 3 * hi[x]);
    const PixelVector v = a * (1.0f - fx) + b * fx;
    if (x + 1 < n)
      store_four(out + 3 * x, v);
    else
      store_three(out + 3 * x, v);
  }
}

// Blocks of F pixels of C interleaved channels, block i reading map pixels
// i and i + 1 of `row` (already at the stretch's first map pixel): the
// same products and sum as the taps' loop, from plain vector loads.
template <int F, int C>
EYESTREAM_VECTOR_CLONES void enlarge_blocks(const float* __restrict row, const float* __restrict w,
                                            float* __restrict out, int blocks) {
  float keep[C * F], take[C * F];
  for (int p = 0; p < F; ++p)
    for (int c = 0; c < C; ++c) keep[C * p + c] = 1.0f - w[p], take[C * p + c] = w[p];
  for (int i = 0; i < blocks; ++i) {
    const float* s = row + C * i;
    float* o = out + C * F * i;
    for (int p = 0; p < F; ++p)
      for (int c = 0; c < C; ++c) o[C * p + c] = s[c] * keep[C * p + c] + s[C + c] * take[C * p + c];
  }
}

template <int C>
void enlarge_stretch(const float* row, const RepeatingTaps& r, float* out, int blocks) {
  const float* from = row + C * r.lo;
  float* to = out + C * r.first;
  if (r.factor == 2) enlarge_blocks<2, C>(from, r.w.data(), to, blocks);
  if (r.factor == 4) enlarge_blocks<4, C>(from, r.w.data(), to, blocks);
  if (r.factor == 8) enlarge_blocks<8, C>(from, r.w.data(), to, blocks);
}

// Pixels [0, n) of `across`: the taps' loop before and after its repeating
// stretch, the blocks within it.
template <int C, typename Taps>
void enlarge(const float* row, const BilinearAxis& across, float* out, int n, Taps taps) {
  const RepeatingTaps& r = across.repeating;
  const int blocks = r.factor == 0 || n <= r.first ? 0 : std::min(r.blocks, (n - r.first) / r.factor);
  if (blocks == 0) return taps(0, n);
  taps(0, r.first);
  enlarge_stretch<C>(row, r, out, blocks);
  taps(r.first + r.factor * blocks, n);
}

}  // namespace

void enlarge_row(const float* row, const BilinearAxis& across, float* out, int n) {
  enlarge<1>(row, across, out, n, [&](int a, int b) {
    enlarge_taps(row, across.lo.data() + a, across.hi.data() + a, across.w.data() + a, out + a, b - a);
  });
}

void enlarge_row3(const float* row, const BilinearAxis& across, float* out, int n) {
  enlarge<3>(row, across, out, n, [&](int a, int b) {
    enlarge_taps3(row, across.lo.data() + a, across.hi.data() + a, across.w.data() + a, out + 3 * a, b - a);
  });
}

EYESTREAM_VECTOR_CLONES
void blend_rows(const float* a, const float* b, float w, float* out, int n) {
  for (int i = 0; i < n; ++i) out[i] = a[i] * (1.0f - w) + b[i] * w;
}

}  // namespace eyestream::retina
