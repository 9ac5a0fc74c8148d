// The stretch of a bilinear axis whose taps repeat: enlarging by a whole
// factor f (2, 4 or 8, as the halved glare frame and the acuity's and the
// afterimages' reduced maps are), pixel first + f i + p reads map pixels
// lo + i and lo + i + 1 with the weight w[p] of the second. There a row can
// be widened a block of f pixels at a time from two neighbouring map pixels,
// with plain vector loads instead of a gather per pixel.
#pragma once

#include <array>
#include <vector>

namespace eyestream::retina {

struct RepeatingTaps {
  int factor = 0;  // 0: no such stretch
  int first = 0;   // its first pixel
  int blocks = 0;  // its blocks of `factor` pixels
  int lo = 0;      // the map pixel its first block reads first
  std::array<float, 8> w{};
};

// The longest stretch that starts where the taps first move on to the next
// map pixel, checked pixel by pixel against lo, hi and w (hi = lo + 1,
// weights bit for bit), for f in {2, 4, 8}.
RepeatingTaps repeating_taps(const std::vector<int>& lo, const std::vector<int>& hi, const std::vector<float>& w);

}  // namespace eyestream::retina
