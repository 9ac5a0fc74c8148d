#include "retina/bilinear_rows.hpp"

#include "retina/vector_clones.hpp"

namespace eyestream::retina {

namespace {

EYESTREAM_VECTOR_CLONES
void enlarge_taps(const float* __restrict row, const int* __restrict lo, const int* __restrict hi,
                  const float* __restrict w, float* __restrict out, int n) {
  for (int x = 0; x < n; ++x) out[x] = row[lo[x]] * (1.0f - w[x]) + row[hi[x]] * w[x];
}

EYESTREAM_VECTOR_CLONES
void enlarge_taps3(const float* __restrict row, const int* __restrict lo, const int* __restrict hi,
                   const float* __restrict w, float* __restrict out, int n) {
  for (int x = 0; x < n; ++x) {
    const float fx = w[x];
    const int x0 = 3 * lo[x], x1 = 3 * hi[x];
    for (int c = 0; c < 3; ++c) out[3 * x + c] = row[x0 + c] * (1.0f - fx) + row[x1 + c] * fx;
  }
}

}  // namespace

void enlarge_row(const float* row, const BilinearAxis& across, float* out, int n) {
  enlarge_taps(row, across.lo.data(), across.hi.data(), across.w.data(), out, n);
}

void enlarge_row3(const float* row, const BilinearAxis& across, float* out, int n) {
  enlarge_taps3(row, across.lo.data(), across.hi.data(), across.w.data(), out, n);
}

EYESTREAM_VECTOR_CLONES
void blend_rows(const float* a, const float* b, float w, float* out, int n) {
  for (int i = 0; i < n; ++i) out[i] = a[i] * (1.0f - w) + b[i] * w;
}

}  // namespace eyestream::retina
