#include "retina/smooth_noise.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace eyestream::retina {

namespace {

// N(0,1) at grid node (i, j, n) by the Box-Muller transform of two hashed uniforms.
float node_value(std::uint64_t seed, RandomStream stream, std::int64_t i, std::int64_t j, std::int64_t n) {
  const std::uint64_t key =
      hash_key(seed, std::uint64_t(stream), std::uint64_t(n), std::uint64_t(i), std::uint64_t(j), 0);
  const double u1 = (double(key >> 11) + 0.5) / 9007199254740992.0;  // (0, 1)
  const double u2 = hash_uniform(mix64(key));
  return float(std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2));
}

double smoothstep(double f) { return f * f * (3.0 - 2.0 * f); }

}  // namespace

cv::Mat smooth_noise(cv::Size size, double t_s, const SmoothNoiseParams& p, std::uint64_t seed, RandomStream stream,
                     cv::Point2d origin) {
  const int gw = int(std::ceil(size.width / p.cell_px)) + 2, gh = int(std::ceil(size.height / p.cell_px)) + 2;
  // The nodes covering the frame, from the one left of and above its first pixel.
  const std::int64_t i0 = std::int64_t(std::floor((0.5 - origin.x) / p.cell_px)),
                     j0 = std::int64_t(std::floor((0.5 - origin.y) / p.cell_px));
  const double tn = t_s / p.period_s;
  const std::int64_t n0 = std::int64_t(std::floor(tn));
  const double wt1 = smoothstep(tn - double(n0)), wt0 = 1.0 - wt1;
  // The two time layers of nodes around t.
  std::vector<float> layer0(size_t(gw) * gh), layer1(size_t(gw) * gh);
  for (int j = 0; j < gh; ++j)
    for (int i = 0; i < gw; ++i) {
      layer0[size_t(j) * gw + i] = node_value(seed, stream, i0 + i, j0 + j, n0);
      layer1[size_t(j) * gw + i] = node_value(seed, stream, i0 + i, j0 + j, n0 + 1);
    }
  // The weights are products wx wy wt, so the sum factors: blend the node
  // rows in time and y once per row, then in x per pixel; and the weights'
  // sum of squares is the product of the three axes' sums.
  std::vector<int> column(size_t(size.width));
  std::vector<double> wx1(size_t(size.width)), sq_x(size_t(size.width));
  for (int x = 0; x < size.width; ++x) {
    const double gx = (x + 0.5 - origin.x) / p.cell_px - double(i0);
    column[size_t(x)] = int(std::floor(gx));
    wx1[size_t(x)] = smoothstep(gx - column[size_t(x)]);
    sq_x[size_t(x)] = wx1[size_t(x)] * wx1[size_t(x)] + (1.0 - wx1[size_t(x)]) * (1.0 - wx1[size_t(x)]);
  }
  const double sq_t = wt0 * wt0 + wt1 * wt1;
  cv::Mat out(size, CV_32F);
  cv::parallel_for_(cv::Range(0, size.height), [&](const cv::Range& rows) {
    std::vector<double> blend(static_cast<size_t>(gw));
    for (int y = rows.start; y < rows.end; ++y) {
      const double gy = (y + 0.5 - origin.y) / p.cell_px - double(j0);
      const int j = int(std::floor(gy));
      const double wy1 = smoothstep(gy - j), wy0 = 1.0 - wy1;
      const float* a0 = &layer0[size_t(j) * gw];
      const float* a1 = &layer1[size_t(j) * gw];
      for (int i = 0; i < gw; ++i)
        blend[size_t(i)] = wt0 * (wy0 * a0[i] + wy1 * a0[i + gw]) + wt1 * (wy0 * a1[i] + wy1 * a1[i + gw]);
      const double sq_ty = sq_t * (wy0 * wy0 + wy1 * wy1);
      float* o = out.ptr<float>(y);
      for (int x = 0; x < size.width; ++x) {
        const size_t i = size_t(column[size_t(x)]);
        const double sum = (1.0 - wx1[size_t(x)]) * blend[i] + wx1[size_t(x)] * blend[i + 1];
        // A weighted sum of independent N(0,1) has variance sum w^2: renormalise.
        o[x] = float(std::clamp(sum / std::sqrt(sq_x[size_t(x)] * sq_ty), -p.clip, p.clip));
      }
    }
  });
  return out;
}

}  // namespace eyestream::retina
