// The two samples, and the weight of the second, that linear resizing
// reads for each output sample, with cv::resize INTER_LINEAR's mapping:
// output sample j reads the input at (j + 0.5) * from_per_to - 0.5,
// clamped to the first and last input samples (weight 0 there). Lets a
// pass bring a reduced image back and combine it with others in one sweep.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace eyestream::glare {

struct LinearTap {
  int a, b;  // input samples
  float wb;  // the weight of b (a's is 1 - wb)
};

// Output samples first .. first + count - 1 from from_size input samples.
inline std::vector<LinearTap> linear_taps(int first, int count, double from_per_to, int from_size) {
  std::vector<LinearTap> taps(static_cast<size_t>(std::max(count, 0)));
  for (int j = 0; j < count; ++j) {
    const double s = (first + j + 0.5) * from_per_to - 0.5;
    int a = int(std::floor(s));
    float wb = float(s - a);
    if (a < 0) a = 0, wb = 0.0f;
    if (a >= from_size - 1) a = from_size - 1, wb = 0.0f;
    taps[size_t(j)] = {a, std::min(a + 1, from_size - 1), wb};
  }
  return taps;
}

}  // namespace eyestream::glare
