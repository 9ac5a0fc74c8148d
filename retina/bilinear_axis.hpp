// Where each pixel of a full-resolution axis reads a reduced map
// bilinearly: pixel i's centre i + 0.5 falls at (i + 0.5) s - 0.5 on the
// map (s = map pixels per full pixel), borders replicated, as cv::resize
// INTER_LINEAR. Computed once per axis, so the per-pixel read is two
// lookups and a blend; where the taps repeat (a whole factor of 2, 4 or 8)
// bilinear_rows.cpp reads blocks of pixels without lookups.
#pragma once

#include <algorithm>
#include <vector>

#include "retina/repeating_taps.hpp"

namespace eyestream::retina {

struct BilinearAxis {
  std::vector<int> lo, hi;
  std::vector<float> w;  // the weight of hi
  RepeatingTaps repeating;  // of lo, hi and w as made here: to be found again if they are changed

  // `full` pixels reading a map of `reduced` pixels at `scale` map pixels
  // per full pixel.
  BilinearAxis(int full, int reduced, float scale) : lo(size_t(full)), hi(size_t(full)), w(size_t(full)) {
    for (int i = 0; i < full; ++i) {
      const float g = std::clamp((float(i) + 0.5f) * scale - 0.5f, 0.0f, float(reduced - 1));
      lo[size_t(i)] = int(g);
      hi[size_t(i)] = std::min(lo[size_t(i)] + 1, reduced - 1);
      w[size_t(i)] = g - float(lo[size_t(i)]);
    }
    repeating = repeating_taps(lo, hi, w);
  }
};

}  // namespace eyestream::retina
