// The two passes of a bilinear enlargement (as cv::resize INTER_LINEAR),
// a row at a time: a reduced row widened across through a BilinearAxis's
// taps, and two widened rows blended down. Compiled for AVX-512 and AVX2
// beside the baseline (vector_clones.hpp; the same bytes either way); a
// three-channel pixel's values at once as one vector; along the axis's
// repeating stretch (repeating_taps.hpp) a block of pixels at a time from
// plain loads, without the taps' lookups; the same products and sums
// throughout. Outputs must not overlap inputs.
#pragma once

#include "retina/bilinear_axis.hpp"

namespace eyestream::retina {

// out[x] = row[lo] (1 - w) + row[hi] w with `across`'s taps of pixel x, for
// n pixels of one channel.
void enlarge_row(const float* row, const BilinearAxis& across, float* out, int n);
// The same for n pixels of three interleaved channels.
void enlarge_row3(const float* row, const BilinearAxis& across, float* out, int n);
// out = a (1 - w) + b w over n values.
void blend_rows(const float* a, const float* b, float w, float* out, int n);

}  // namespace eyestream::retina
