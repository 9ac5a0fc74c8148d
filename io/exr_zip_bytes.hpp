// The two byte transforms OpenEXR's ZIP and ZIPS compression apply before
// deflate, undone: the predictor (each byte stored as its difference from
// the one before, plus 128) and the reordering (the even bytes first, then
// the odd). Vector loops; tests/exr_zip_bytes_test.cpp holds them to the
// transforms written out a byte at a time.
#pragma once

#include <cstddef>

namespace eyestream::io {

// t[i] = t[i - 1] + t[i] - 128 (mod 256) for i = 1 .. n - 1, in place.
void undo_zip_predictor(unsigned char* t, size_t n);

// out[2 i] = in[i], out[2 i + 1] = in[(n + 1) / 2 + i]: the n bytes of
// `in`, whose first (n + 1) / 2 are the even ones, back in order.
void undo_zip_reorder(const unsigned char* in, unsigned char* out, size_t n);

}  // namespace eyestream::io
