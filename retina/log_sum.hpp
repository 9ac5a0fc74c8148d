// The sum of log2 over a row of positive finite floats, in double, with no
// call to the library's log per value: the loop runs as vectors (AVX-512
// and AVX2 versions beside the baseline, vector_clones.hpp). Each value is
// split as 2^e m with m in [sqrt(1/2), sqrt(2)), and log(m) is the series
// 2 atanh(s) = 2 (s + s^3/3 + ... + s^17/17), s = (m - 1) / (m + 1): with
// |s| < 0.172 its first omitted term is below 1e-15, so each value's log2
// is within 1e-15 plus four units in the last place of the result of the
// exact one (tests/log_sum_test.cpp). The sum is
// made in eight partial sums added in a fixed order: the same value on any
// machine and thread count. For geometric means of luminance.
#pragma once

namespace eyestream::retina {

// sum over [0, n) of log2(v[i]); every v[i] must be positive and finite.
double log2_sum(const float* v, int n);

}  // namespace eyestream::retina
