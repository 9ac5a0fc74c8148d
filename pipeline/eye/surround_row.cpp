#include "pipeline/eye/surround_row.hpp"

#include <algorithm>

#include "retina/vector_clones.hpp"

namespace eyestream::pipeline {

namespace {

constexpr int kChunk = 256;  // pixels a step: the running shares stay on the stack

EYESTREAM_VECTOR_CLONES
void add_coloured(const float* m, float w, float* inside, int n) {
  for (int i = 0; i < n; ++i) inside[i] += w * m[i];
}

EYESTREAM_VECTOR_CLONES
void add_grey(const float* m, float w, float* inside, int pixels) {
  for (int x = 0; x < pixels; ++x) {
    const float v = w * m[x];
    inside[3 * x] += v;
    inside[3 * x + 1] += v;
    inside[3 * x + 2] += v;
  }
}

// The three grey components interleaved in m, added in their order (each
// channel's sum as add_grey would leave it after three calls).
EYESTREAM_VECTOR_CLONES
void add_grey_triple(const float* m, float w0, float w1, float w2, float* inside, int pixels) {
  for (int x = 0; x < pixels; ++x) {
    const float v0 = w0 * m[3 * x], v1 = w1 * m[3 * x + 1], v2 = w2 * m[3 * x + 2];
    inside[3 * x] = inside[3 * x] + v0 + v1 + v2;
    inside[3 * x + 1] = inside[3 * x + 1] + v0 + v1 + v2;
    inside[3 * x + 2] = inside[3 * x + 2] + v0 + v1 + v2;
  }
}

EYESTREAM_VECTOR_CLONES
void add_outside(const float* inside, float s, float* out, int n) {
  for (int i = 0; i < n; ++i) out[i] += s * std::max(0.0f, 1.0f - inside[i]);
}

}  // namespace

void add_surround_row(const SurroundShares& shares, const std::array<float, 4>& weights, cv::Vec3f kept, float s,
                      float* row, int cols) {
  float inside[3 * kChunk];
  // The maps' weights follow the triple's three; one component alone takes 1.
  const std::size_t first = shares.triple ? 3 : 0;
  std::array<float, 4> map_weight{};
  for (std::size_t c = 0; c < shares.count; ++c) map_weight[c] = first + shares.count == 1 ? 1.0f : weights[first + c];
  for (int x0 = 0; x0 < cols; x0 += kChunk) {
    const int pixels = std::min(kChunk, cols - x0);
    for (int x = 0; x < pixels; ++x) {
      inside[3 * x] = kept[0];
      inside[3 * x + 1] = kept[1];
      inside[3 * x + 2] = kept[2];
    }
    if (shares.triple) add_grey_triple(shares.triple + 3 * x0, weights[0], weights[1], weights[2], inside, pixels);
    for (std::size_t c = 0; c < shares.count; ++c) {
      const float w = map_weight[c];
      if (shares.strides[c] == 3)
        add_coloured(shares.maps[c] + 3 * x0, w, inside, 3 * pixels);
      else
        add_grey(shares.maps[c] + x0, w, inside, pixels);
    }
    add_outside(inside, s, row + 3 * x0, 3 * pixels);
  }
}

}  // namespace eyestream::pipeline
