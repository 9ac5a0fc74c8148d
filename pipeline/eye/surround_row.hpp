// The light a uniform surround beyond the frame scatters into one frame
// row: s times the share of each pixel's PSF that falls outside the frame,
// 1 - (the kept share + the in-frame shares of the PSF's components,
// weighted). Vectorised over the row (vector_clones.hpp, no FMA: the same
// bytes as a per-pixel loop).
#pragma once

#include <array>
#include <cstddef>
#include <opencv2/core.hpp>

namespace eyestream::pipeline {

struct SurroundShares {
  // The first three components' in-frame shares of the row (each grey),
  // interleaved: 3 floats a pixel, one a component; or null.
  const float* triple = nullptr;
  // Each further component's in-frame share of the row, 3 floats a pixel
  // (coloured, stride 3) or 1 (grey, stride 1); `count` of them.
  std::array<const float*, 4> maps{};
  std::array<int, 4> strides{};
  std::size_t count = 0;
};

// row[3x + k] += s max(0, 1 - inside_k(x)), where inside = kept + the sum
// over the components, in order (the triple's three, then the maps'), of
// weight_c times the share (a grey share in every channel); one component
// alone takes weight 1.
void add_surround_row(const SurroundShares& shares, const std::array<float, 4>& weights, cv::Vec3f kept, float s,
                      float* row, int cols);

}  // namespace eyestream::pipeline
