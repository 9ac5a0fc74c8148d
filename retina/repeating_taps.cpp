#include "retina/repeating_taps.hpp"

#include <cstring>

namespace eyestream::retina {

namespace {

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

RepeatingTaps repeating_taps(const std::vector<int>& lo, const std::vector<int>& hi, const std::vector<float>& w) {
  RepeatingTaps r;
  const int n = int(lo.size());
  int first = 1;
  while (first < n && lo[size_t(first)] == lo[size_t(first - 1)]) ++first;
  int f = 1;
  while (first + f < n && lo[size_t(first + f)] == lo[size_t(first)]) ++f;
  if (first >= n || (f != 2 && f != 4 && f != 8)) return r;
  r.factor = f;
  r.first = first;
  r.lo = lo[size_t(first)];
  for (int p = 0; p < f; ++p) r.w[size_t(p)] = w[size_t(first + p)];
  for (int i = 0;; ++i) {
    const int start = first + f * i;
    if (start + f > n) break;
    for (int p = 0; p < f; ++p) {
      const size_t x = size_t(start + p);
      if (lo[x] != r.lo + i || hi[x] != lo[x] + 1 || !same_bits(w[x], r.w[size_t(p)])) return r;
    }
    r.blocks = i + 1;
  }
  return r;
}

}  // namespace eyestream::retina
