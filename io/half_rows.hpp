// Rows of half floats (an EXR's usual channels) to interleaved float
// pixels, by integer arithmetic on the bits: a loop the compiler runs as
// vectors, where OpenEXR converts one value at a time while it copies
// (its copyIntoFrameBuffer was 3.6 % of a `fast` run's CPU on half-float
// input). Exact: every half is a float (tests/half_rows_test.cpp checks all
// 65536 against Imath's conversion).
#pragma once

#include <cstdint>

namespace eyestream::io {

// rgb[3 x + c] = the half in channel c's row at x, for x < n (red, green,
// blue rows, each n halves).
void halves_to_rgb(const std::uint16_t* red, const std::uint16_t* green, const std::uint16_t* blue, float* rgb, int n);

// rgb[3 x + c] = the half in `grey` at x, for every c.
void halves_to_grey_rgb(const std::uint16_t* grey, float* rgb, int n);

}  // namespace eyestream::io
