#include "retina/display_encoding.hpp"

#include <algorithm>
#include <cmath>

#include "retina/hash_random.hpp"
#include "retina/pow_table.hpp"

namespace eyestream::retina {

namespace {

template <typename T>
void encode_rows(const cv::Mat& linear, std::int64_t frame, const EncodingParams& p, float max_code, cv::Mat& code) {
  const PowTable& gamma = shared_pow_table(p.gamma);  // 1e-7 relative: below 1e-2 of a 16-bit code
  cv::parallel_for_(cv::Range(0, linear.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const cv::Vec3f* in = linear.ptr<cv::Vec3f>(y);
      T* out = code.ptr<T>(y);
      const std::uint64_t row_key =
          hash_row(p.seed, std::uint64_t(RandomStream::kDither), std::uint64_t(frame), std::uint64_t(y));
      for (int x = 0; x < linear.cols; ++x) {
        const std::uint64_t key = p.dither ? hash_pixel(row_key, std::uint64_t(x)) : 0;
        for (int c = 0; c < 3; ++c) {
          float j = in[x][c];
          j = std::isfinite(j) ? std::clamp(j, 0.0f, 1.0f) : 0.0f;
          const float v = gamma(j) * max_code;
          float q;
          if (p.dither) {
            // docs/model.md: round up with probability equal to the fractional part.
            const float lo = std::floor(v);
            q = lo + ((v - lo) > hash_uniform3(key, c) ? 1.0f : 0.0f);
          } else {
            q = std::nearbyint(v);
          }
          out[3 * x + c] = T(std::min(q, max_code));
        }
      }
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
