#include "retina/display_encoding.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

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

// The dither's three uniforms of each pixel (hash_uniform3 of its key).
EYESTREAM_VECTOR_CLONES
void dither_row(std::uint64_t row_key, int pixels, float* u) {
  for (int x = 0; x < pixels; ++x) {
    const std::uint64_t key = hash_pixel(row_key, std::uint64_t(x));
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

template <typename T>
void encode_rows(const cv::Mat& linear, std::int64_t frame, const EncodingParams& p, float max_code, cv::Mat& code) {
  const PowTable& gamma = shared_pow_table(p.gamma);  // 1e-7 relative: below 1e-2 of a 16-bit code
  const int n = 3 * linear.cols;
  cv::parallel_for_(cv::Range(0, linear.rows), [&](const cv::Range& rows) {
    const size_t values = static_cast<size_t>(n);
    std::vector<float> j(values), g(values), u(p.dither ? values : 0), q(values);
    for (int y = rows.start; y < rows.end; ++y) {
      clamp_row(linear.ptr<float>(y), j.data(), n);
      gamma.batch(j.data(), g.data(), n);
      if (p.dither)
        dither_row(hash_row(p.seed, std::uint64_t(RandomStream::kDither), std::uint64_t(frame), std::uint64_t(y)),
                   linear.cols, u.data());
      quantise_row(g.data(), p.dither ? u.data() : nullptr, max_code, q.data(), n);
      T* out = code.ptr<T>(y);
      for (int i = 0; i < n; ++i) out[i] = T(q[i]);
    }
  });
}

}  // namespace

void encode_display(const cv::Mat& linear, int bits, std::int64_t frame_index, const EncodingParams& p, cv::Mat& code) {
  CV_Assert(linear.type() == CV_32FC3 && (bits == 8 || bits == 16));
  if (bits == 8) {
    code.create(linear.size(), CV_8UC3);
    encode_rows<std::uint8_t>(linear, frame_index, p, 255.0f, code);
  } else {
    code.create(linear.size(), CV_16UC3);
    encode_rows<std::uint16_t>(linear, frame_index, p, 65535.0f, code);
  }
}

}  // namespace eyestream::retina
