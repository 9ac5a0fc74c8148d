#include "io/exr_zip_bytes.hpp"

#include <cstring>

namespace eyestream::io {

namespace {

// Sixteen bytes as one vector (GCC's and Clang's vector extension), whose
// adds wrap modulo 256 as the predictor's do.
typedef unsigned char Bytes __attribute__((vector_size(16)));

// x moved up k bytes, zeros in from the bottom.
template <int k>
Bytes up(const Bytes& x) {
  const Bytes zero = {};
  if constexpr (k == 1)
    return __builtin_shufflevector(zero, x, 0, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30);
  else if constexpr (k == 2)
    return __builtin_shufflevector(zero, x, 0, 0, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29);
  else if constexpr (k == 4)
    return __builtin_shufflevector(zero, x, 0, 0, 0, 0, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27);
  else
    return __builtin_shufflevector(zero, x, 0, 0, 0, 0, 0, 0, 0, 0, 16, 17, 18, 19, 20, 21, 22, 23);
}

}  // namespace

void undo_zip_predictor(unsigned char* t, size_t n) {
  if (n < 2) return;
  // A running sum of (t[i] - 128) from t[0]: each block's own running sum
  // in four shifted adds, then the last byte before the block added.
  // The last byte is carried from block to block in every lane of a
  // vector: one shuffle and one add on the chain a block.
  const unsigned char first = t[0];
  Bytes last = {first, first, first, first, first, first, first, first,
                first, first, first, first, first, first, first, first};
  size_t i = 1;
  const Bytes bias = {128, 128, 128, 128, 128, 128, 128, 128, 128, 128, 128, 128, 128, 128, 128, 128};
  for (; i + sizeof(Bytes) <= n; i += sizeof(Bytes)) {
    Bytes x;
    std::memcpy(&x, t + i, sizeof x);
    x -= bias;
    x += up<1>(x);
    x += up<2>(x);
    x += up<4>(x);
    x += up<8>(x);
    x += last;
    std::memcpy(t + i, &x, sizeof x);
    last = __builtin_shufflevector(x, x, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15);
  }
  unsigned char carried = last[0];
  for (; i < n; ++i) t[i] = carried = static_cast<unsigned char>(carried + t[i] - 128);
}

void undo_zip_reorder(const unsigned char* in, unsigned char* out, size_t n) {
  const unsigned char* even = in;
  const unsigned char* odd = in + (n + 1) / 2;
  const size_t pairs = n / 2;
  for (size_t i = 0; i < pairs; ++i) {
    out[2 * i] = even[i];
    out[2 * i + 1] = odd[i];
  }
  if (n % 2) out[n - 1] = even[pairs];
}

}  // namespace eyestream::io
