#include "glare/channel_rows.hpp"

#include <algorithm>

#include "glare/vector_clones.hpp"

namespace eyestream::glare {

EYESTREAM_VECTOR_CLONES
void split_row(const float* in, int n, double* r0, double* r1, double* r2) {
  for (int x = 0; x < n; ++x) {
    r0[x] = double(in[3 * x]);
    r1[x] = double(in[3 * x + 1]);
    r2[x] = double(in[3 * x + 2]);
  }
}

namespace {

// Four floats, and four doubles, as vectors (GCC's and Clang's vector
// extension), loaded from and stored to any float or double.
typedef float Float4 __attribute__((vector_size(16)));
typedef float LooseFloat4 __attribute__((vector_size(16), aligned(4)));
typedef double Double4 __attribute__((vector_size(32)));
typedef double LooseDouble4 __attribute__((vector_size(32), aligned(8)));

// float(max(r scale, 0)) of four values, as std::max gives it (a NaN or
// -0 product kept).
inline Float4 scaled_floor(const double* r, double scale) {
  const Double4 v = *reinterpret_cast<const LooseDouble4*>(r) * scale;
  const Double4 zero = {0, 0, 0, 0};
  return __builtin_convertvector(v < zero ? zero : v, Float4);
}

}  // namespace

// One output row from each channel's result, scaled, negative residue set
// to 0. Four pixels at a time: each channel's four values, interleaved by
// shuffles into three stores (as a loop over values the compiler did not
// vectorise the interleaving).
EYESTREAM_VECTOR_CLONES
void merge_row(const double* r0, const double* r1, const double* r2, double scale, int n, float* out) {
  int x = 0;
  for (; x + 4 <= n; x += 4) {
    const Float4 a = scaled_floor(r0 + x, scale), b = scaled_floor(r1 + x, scale), c = scaled_floor(r2 + x, scale);
    float* o = out + 3 * x;  // a0 b0 c0 a1 | b1 c1 a2 b2 | c2 a3 b3 c3
    *reinterpret_cast<LooseFloat4*>(o) =
        __builtin_shufflevector(__builtin_shufflevector(a, b, 0, 4, 1, 5), c, 0, 1, 4, 2);
    *reinterpret_cast<LooseFloat4*>(o + 4) =
        __builtin_shufflevector(__builtin_shufflevector(b, c, 1, 5, 2, 6), a, 0, 1, 6, 2);
    *reinterpret_cast<LooseFloat4*>(o + 8) =
        __builtin_shufflevector(c, __builtin_shufflevector(a, b, 3, 7, 3, 7), 2, 4, 5, 3);
  }
  for (; x < n; ++x) {
    out[3 * x] = float(std::max(r0[x] * scale, 0.0));
    out[3 * x + 1] = float(std::max(r1[x] * scale, 0.0));
    out[3 * x + 2] = float(std::max(r2[x] * scale, 0.0));
  }
}

EYESTREAM_VECTOR_CLONES
void channel_to_row(const float* rgb, int c, int n, double* row) {
  for (int x = 0; x < n; ++x) row[x] = double(rgb[3 * x + c]);
}

EYESTREAM_VECTOR_CLONES
void row_to_channel(const double* row, double scale, int c, int n, float* rgb) {
  for (int x = 0; x < n; ++x) rgb[3 * x + c] = float(std::max(row[x] * scale, 0.0));
}

}  // namespace eyestream::glare
