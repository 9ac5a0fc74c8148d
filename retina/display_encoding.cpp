#include "retina/display_encoding.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "retina/hash_random.hpp"
#include "retina/pow_table.hpp"
#include "retina/vector_clones.hpp"

namespace eyestream::retina {

namespace {

// One row's steps, each a plain loop over its values that the compiler
// vectorises (vector_clones.hpp; no FMA: the same bytes either way).

// Non-finite to 0, the rest clamped to [0, 1] (-0 to +0: the gamma table
// reads the float's bits).
EYESTREAM_VECTOR_CLONES
void clamp_row(const float* in, float* out, int n) {
  for (int i = 0; i < n; ++i) {
    std::uint32_t bits;
    std::memcpy(&bits, &in[i], sizeof bits);
    const bool finite = (bits & 0x7f800000u) != 0x7f800000u;
    float v = in[i] > 0.0f ? in[i] : 0.0f;  // (NaN fails the test: 0)
    v = v < 1.0f ? v : 1.0f;
    out[i] = finite ? v : 0.0f;
  }
}

// The dither's three uniforms of each of `pixels` pixels from column x0
// on (hash_uniform3 of its key).
EYESTREAM_VECTOR_CLONES
void dither_row(std::uint64_t row_key, int x0, int pixels, float* u) {
  for (int x = 0; x < pixels; ++x) {
    const std::uint64_t key = hash_pixel(row_key, std::uint64_t(x0 + x));
    for (int c = 0; c < 3; ++c) u[3 * x + c] = hash_uniform3(key, c);
  }
}

// v = g max_code, rounded up with probability equal to its fractional
// part (docs/model.md), or to nearest without dither (u null).
EYESTREAM_VECTOR_CLONES
void quantise_row(const float* g, const float* u, float max_code, float* q, int n) {
  if (u) {
    for (int i = 0; i < n; ++i) {
      const float v = g[i] * max_code, lo = float(int(v));  // (v >= 0: truncation is the floor)
      const float up = (v - lo) > u[i] ? 1.0f : 0.0f;
      const float code = lo + up;
      q[i] = code < max_code ? code : max_code;
    }
  } else {
    for (int i = 0; i < n; ++i) q[i] = std::min(std::nearbyint(g[i] * max_code), max_code);
  }
}

constexpr int kChunk = 256;  // pixels a step: each step's values stay on the stack

template <typename T>
void encode_row(const float* linear, int cols, int y, std::int64_t frame, const EncodingParams& p,
                const PowTable& gamma, float max_code, T* out) {
  const std::uint64_t row_key =
      p.dither ? hash_row(p.seed, std::uint64_t(RandomStream::kDither), std::uint64_t(frame), std::uint64_t(y)) : 0;
  float j[3 * kChunk], g[3 * kChunk], u[3 * kChunk], q[3 * kChunk];
  for (int x0 = 0; x0 < cols; x0 += kChunk) {
    const int pixels = std::min(kChunk, cols - x0), n = 3 * pixels;
    clamp_row(linear + 3 * x0, j, n);
    gamma.batch(j, g, n);
    if (p.dither) dither_row(row_key, x0, pixels, u);
    quantise_row(g, p.dither ? u : nullptr, max_code, q, n);
    for (int i = 0; i < n; ++i) out[3 * x0 + i] = T(q[i]);
  }
}

void encode_row_in_bits(const float* linear, int cols, int y, std::int64_t frame_index, const EncodingParams& p,
                        const PowTable& gamma, int bits, void* code_row) {
  if (bits == 8)
    encode_row(linear, cols, y, frame_index, p, gamma, 255.0f, static_cast<std::uint8_t*>(code_row));
  else
    encode_row(linear, cols, y, frame_index, p, gamma, 65535.0f, static_cast<std::uint16_t*>(code_row));
}

}  // namespace

void encode_display_row(const float* linear, int cols, int y, std::int64_t frame_index, const EncodingParams& p,
                        int bits, void* code_row) {
  CV_Assert(bits == 8 || bits == 16);
  encode_row_in_bits(linear, cols, y, frame_index, p, shared_pow_table(p.gamma), bits, code_row);
}

void encode_display(const cv::Mat& linear, int bits, std::int64_t frame_index, const EncodingParams& p, cv::Mat& code) {
  CV_Assert(linear.type() == CV_32FC3 && (bits == 8 || bits == 16));
  const PowTable& gamma = shared_pow_table(p.gamma);  // 1e-7 relative: below 1e-2 of a 16-bit code
  code.create(linear.size(), bits == 8 ? CV_8UC3 : CV_16UC3);
  cv::parallel_for_(cv::Range(0, linear.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y)
      encode_row_in_bits(linear.ptr<float>(y), linear.cols, y, frame_index, p, gamma, bits, code.ptr(y));
  });
}

}  // namespace eyestream::retina
