// An image row's interleaved float channels to rows of doubles for the
// FFT engines, and back: every channel in one sweep (one channel at a
// time, each sweep read the whole interleaved row again), or one channel
// where the engine holds one channel's spectrum at a time.
// Compiled for AVX-512 and AVX2 beside the baseline (vector_clones.hpp: no
// FMA, so every version gives the same bytes).
#pragma once

namespace eyestream::glare {

// r0[x], r1[x], r2[x] = the channels of the n interleaved pixels in[0..n).
void split_row(const float* in, int n, double* r0, double* r1, double* r2);

// The n interleaved pixels out[0..n) = float(max(r scale, 0)) of each
// channel's row, as std::max gives it (a NaN or -0 product kept).
void merge_row(const double* r0, const double* r1, const double* r2, double scale, int n, float* out);

// row[x] = channel c of the n interleaved RGB pixels rgb[0..n).
void channel_to_row(const float* rgb, int c, int n, double* row);

// Channel c of the n interleaved RGB pixels rgb[0..n) = float(max(row[x]
// scale, 0)).
void row_to_channel(const double* row, double scale, int c, int n, float* rgb);

}  // namespace eyestream::glare
