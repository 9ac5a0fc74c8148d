// A bilinear splat's shares, written out for the tests' oracles: a point
// at (tx, ty) in plane pixel coordinates (pixel centres at integers) gives
// each of the four plane pixels around it the product of its distances'
// complements, those beyond the plane dropped.
#pragma once

#include <cmath>
#include <opencv2/core.hpp>

namespace eyestream::test {

// add(i, j, share) for each of the four pixels around (tx, ty) inside `plane`.
template <typename Add>
void for_each_bilinear_share(double tx, double ty, cv::Size plane, const Add& add) {
  const int i0 = int(std::floor(tx)), j0 = int(std::floor(ty));
  const double fx = tx - i0, fy = ty - j0;
  for (int dj = 0; dj < 2; ++dj)
    for (int di = 0; di < 2; ++di) {
      const int i = i0 + di, j = j0 + dj;
      if (i < 0 || j < 0 || i >= plane.width || j >= plane.height) continue;
      add(i, j, (di ? fx : 1.0 - fx) * (dj ? fy : 1.0 - fy));
    }
}

}  // namespace eyestream::test
