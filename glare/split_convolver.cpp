#include "glare/split_convolver.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "glare/vector_clones.hpp"

namespace eyestream::glare {

namespace {

constexpr double kHaloOuterDeg = 4.5;  // Spencer et al. 1995: the halo ring's outer edge

// A window over r in full-resolution pixels: 1 within `from`, falling
// linearly to 0 at `to`.
struct Window {
  double from, to;
  double at(double r) const {
    if (r <= from) return 1.0;
    if (r >= to) return 0.0;
    return (to - r) / (to - from);
  }
};

// The middle level blurs its band: the block sums (a box, f^2 / 12 px^2
// of variance along each axis) and the bilinear enlargement (a tent,
// f^2 / 6), softening the PSF's steep part beyond the near window and the
// flare lines drawn in it. The band is sharpened to second order,
// K - c lap(K), the Laplacian in blocks (five points; it sums to 0, so no
// energy is added): c = 1/8 block^2 undoes f^2 / 4 px^2. Measured
// (docs/performance.md): `balanced`'s p99 CIEDE2000 on the 720p night city
// 1.16 unsharpened, 1.02 at 1/8, 1.01 at 1/6; the headlights with flare
// lines at factor 4 came to 96 % of their stated error at 1/8 and 100 % at
// 1/6 (tests/split_engine_test.cpp): the lines, a block or two wide,
// overshoot at their edges when sharpened more.
constexpr double kMiddleSharpening = 1.0 / 8.0;

// kernel -= c lap(kernel).
void sharpen(cv::Mat& kernel, double c) {
  cv::Mat lap;
  cv::Laplacian(kernel, lap, CV_64F, 1, 1.0, 0.0, cv::BORDER_CONSTANT);
  kernel -= c * lap;
}

// Every component kernel of `k`, for loops over them.
std::vector<cv::Mat*> components(ComponentKernels& k) {
  return {&k.core, &k.inner, &k.outer, &k.halo[0], &k.halo[1], &k.halo[2]};
}

// Multiplies `kernel` (centred) by window(r * pixel_scale), or by
// 1 - window when `complement`; r in the kernel's pixels.
void apply_window(cv::Mat& kernel, double pixel_scale, Window window, bool complement) {
  const double cx = kernel.cols / 2, cy = kernel.rows / 2;
  for (int y = 0; y < kernel.rows; ++y) {
    double* row = kernel.ptr<double>(y);
    for (int x = 0; x < kernel.cols; ++x) {
      const double w = window.at(std::hypot(x - cx, y - cy) * pixel_scale);
      row[x] *= complement ? 1.0 - w : w;
    }
  }
}

// Multiplies `kernel` (centred) by outer(r) - inner(r), r = the distance
// in full-resolution pixels (pixel_scale per kernel pixel).
void apply_band(cv::Mat& kernel, double pixel_scale, Window inner, Window outer) {
  const double cx = kernel.cols / 2, cy = kernel.rows / 2;
  for (int y = 0; y < kernel.rows; ++y) {
    double* row = kernel.ptr<double>(y);
    for (int x = 0; x < kernel.cols; ++x) {
      const double r = std::hypot(x - cx, y - cy) * pixel_scale;
      row[x] *= outer.at(r) - inner.at(r);
    }
  }
}

// Sums of `m`'s by x by blocks (zero beyond its edges) into a `size` image.
cv::Mat block_sums(const cv::Mat& m, int by, cv::Size size) {
  cv::Mat sums(size, CV_32FC3);
  cv::parallel_for_(cv::Range(0, size.height), [&](const cv::Range& rows) {
    for (int v = rows.start; v < rows.end; ++v) {
      cv::Vec3f* out = sums.ptr<cv::Vec3f>(v);
      std::fill(out, out + size.width, cv::Vec3f());
      // Each block's pixels in the order a sweep along the row meets them,
      // whole blocks first (no division per pixel), then the cut last one.
      const int whole = m.cols / by;
      for (int y = v * by; y < std::min((v + 1) * by, m.rows); ++y) {
        const cv::Vec3f* in = m.ptr<cv::Vec3f>(y);
        for (int u = 0; u < whole; ++u) {
          cv::Vec3f sum = out[u];
          for (int k = 0; k < by; ++k) sum += in[u * by + k];
          out[u] = sum;
        }
        for (int x = whole * by; x < m.cols; ++x) out[whole] += in[x];
      }
    }
  });
  return sums;
}

struct Source {
  int x, y;
  cv::Vec3f value;
};

// The flat loops of the enlargements, compiled for AVX-512 and AVX2
// beside the baseline (glare/vector_clones.hpp: no FMA, so every version
// gives the same bytes).

// wide[3x + c] = m[3 a + c] (1 - wb) + m[3 b + c] wb for each output pixel x's taps.
EYESTREAM_VECTOR_CLONES
void widen_row(const float* m, const LinearTap* taps, int width, float* wide) {
  for (int x = 0; x < width; ++x) {
    const float* pa = m + 3 * taps[x].a;
    const float* pb = m + 3 * taps[x].b;
    const float wa = 1.0f - taps[x].wb, wb = taps[x].wb;
    for (int c = 0; c < 3; ++c) wide[3 * x + c] = pa[c] * wa + pb[c] * wb;
  }
}

// Eight pixels' channel pattern of a per-channel factor.
struct ChannelPattern {
  float v[24];
  explicit ChannelPattern(const float s[3]) {
    for (int i = 0; i < 24; ++i) v[i] = s[i % 3];
  }
};

// out[i] = max(out[i] + (top[i] (1 - wb) + bottom[i] wb) scale[i % 3], 0)
// over n = 3 x pixels values, or out[i] += ... without the max.
template <bool kFloor>
void blend_into_impl(const float* top, const float* bottom, float wb, const ChannelPattern& scale, int n, float* out) {
  const float wa = 1.0f - wb;
  int i0 = 0;
  for (; i0 + 24 <= n; i0 += 24)
    for (int k = 0; k < 24; ++k) {
      const float v = out[i0 + k] + (top[i0 + k] * wa + bottom[i0 + k] * wb) * scale.v[k];
      out[i0 + k] = kFloor ? std::max(v, 0.0f) : v;
    }
  for (int k = 0; i0 + k < n; ++k) {
    const float v = out[i0 + k] + (top[i0 + k] * wa + bottom[i0 + k] * wb) * scale.v[k];
    out[i0 + k] = kFloor ? std::max(v, 0.0f) : v;
  }
}

EYESTREAM_VECTOR_CLONES
void blend_into_floored(const float* top, const float* bottom, float wb, const ChannelPattern& scale, int n,
                        float* out) {
  blend_into_impl<true>(top, bottom, wb, scale, n, out);
}

EYESTREAM_VECTOR_CLONES
void blend_into(const float* top, const float* bottom, float wb, const ChannelPattern& scale, int n, float* out) {
  blend_into_impl<false>(top, bottom, wb, scale, n, out);
}

// out += `m` enlarged by `up` times `scale` per channel (floored at 0 when
// kFloor), in stripes of rows that widen each input row once.
template <bool kFloor>
void add_enlarged(const cv::Mat& m, const std::vector<LinearTap>& up_x, const std::vector<LinearTap>& up_y,
                  const float scale[3], cv::Mat& out) {
  CV_Assert(m.type() == CV_32FC3 && out.type() == CV_32FC3 && int(up_x.size()) >= out.cols &&
            int(up_y.size()) >= out.rows);
  const ChannelPattern pattern(scale);
  const int width = out.cols;
  cv::parallel_for_(
      cv::Range(0, out.rows),
      [&](const cv::Range& rows) {
        cv::Mat widened(2, width, CV_32FC3);  // two input rows across the output, in slots row % 2
        int held[2] = {-1, -1};
        const auto row_of = [&](int v) {
          float* wide = widened.ptr<float>(v % 2);
          if (held[v % 2] != v) {
            widen_row(m.ptr<float>(v), up_x.data(), width, wide);
            held[v % 2] = v;
          }
          return wide;
        };
        for (int y = rows.start; y < rows.end; ++y) {
          const LinearTap& ty = up_y[size_t(y)];
          const float* top = row_of(ty.a);
          const float* bottom = ty.b == ty.a ? top : row_of(ty.b);
          if (kFloor)
            blend_into_floored(top, bottom, ty.wb, pattern, 3 * width, out.ptr<float>(y));
          else
            blend_into(top, bottom, ty.wb, pattern, 3 * width, out.ptr<float>(y));
        }
      },
      double(std::max(1, cv::getNumThreads()) * 4));
}

// Per channel, want / got (0 where nothing was got).
struct EnergyScale {
  float v[3];
  operator const float*() const { return v; }
};
EnergyScale energy_scale(const cv::Vec3d& want, const cv::Vec3d& got) {
  EnergyScale s;
  for (int c = 0; c < 3; ++c) s.v[c] = got[c] > 0 ? float(want[c] / got[c]) : 0.0f;
  return s;
}

// A width x height frame padded to whole blocks of `block` pixels.
cv::Size padded(int width, int height, int block) {
  return {(width + block - 1) / block * block, (height + block - 1) / block * block};
}

}  // namespace

SplitConvolver::Enlargement::Enlargement(cv::Size from, cv::Size to)
    : x(linear_taps(0, to.width, double(from.width) / to.width, from.width)),
      y(linear_taps(0, to.height, double(from.height) / to.height, from.height)),
      column_weight(size_t(from.width), 0.0),
      row_weight(size_t(from.height), 0.0) {
  for (const LinearTap& t : x) column_weight[size_t(t.a)] += 1.0 - t.wb, column_weight[size_t(t.b)] += t.wb;
  for (const LinearTap& t : y) row_weight[size_t(t.a)] += 1.0 - t.wb, row_weight[size_t(t.b)] += t.wb;
}

SplitConvolver::Enlargement::Totals SplitConvolver::Enlargement::totals(const cv::Mat& m) const {
  CV_Assert(m.type() == CV_32FC3 && m.cols == int(column_weight.size()) && m.rows == int(row_weight.size()));
  // Both totals in one pass: the input's in double in pixel order (as
  // cv::sum adds a three-channel float image, to the same bytes), the
  // enlargement's through the rows' and columns' weights.
  Totals t;
  for (int v = 0; v < m.rows; ++v) {
    const cv::Vec3f* p = m.ptr<cv::Vec3f>(v);
    cv::Vec3d weighted;
    for (int u = 0; u < m.cols; ++u) {
      const cv::Vec3d x(p[u]);
      t.input += x;
      weighted += x * column_weight[size_t(u)];
    }
    t.enlarged += weighted * row_weight[size_t(v)];
  }
  return t;
}

SplitConvolver::SplitConvolver(int width, int height, double ppd, int factor, const EyeOptics& optics,
                               bool with_centre)
    : width_(width), height_(height), factor_(std::max(factor, 2)), radius_(8 * factor_),
      tail_up_(padded(width, height, 4 * factor_) / (4 * factor_), padded(width, height, 4 * factor_) / factor_),
      middle_up_(padded(width, height, 4 * factor_) / factor_, padded(width, height, 4 * factor_)) {
  const int f1 = factor_, f2 = 4 * factor_;
  const int padded_w = (width + f2 - 1) / f2 * f2, padded_h = (height + f2 - 1) / f2 * f2;
  // The windows in full-resolution pixels. The near one falls from R_0 / 2
  // to R_0. The tail starts beyond the lenticular halo (rings up to 4.5
  // deg, coloured at a scale its blocks would blur) and where its blocks
  // are small against the PSF's change (8 of them); it takes over in a
  // ramp half its start wide, and at least 8 of its blocks (a third as
  // wide doubled the error there: tests/split_engine_test.cpp).
  const double r0 = radius_;
  const Window w0{r0 / 2.0, r0};
  const double from1 = std::max(8.0 * f2, kHaloOuterDeg * ppd);
  const Window w1{from1, from1 + std::max(from1 / 2.0, 8.0 * f2)};
  const double r1 = w1.to;
  near_ = build_component_kernels(radius_ + 1, radius_ + 1, ppd, optics);
  for (cv::Mat* k : components(near_)) {
    apply_window(*k, 1.0, w0, false);
    if (!with_centre) k->at<double>(near_.centre()) = 0.0;
  }
  // Tiles need less memory (their spectra and buffers are a tile's size,
  // 50 + 17 MB less at 1080p and factor 2) and took the same time as the
  // whole frame where a tile's window is mostly output (factor 2: 0.77),
  // 6 ms more at factor 4 (0.56; docs/performance.md).
  if (tile_output_share(radius_) >= 0.7)
    near_tiles_ = std::make_unique<TiledConvolver>(near_, width, height);
  else
    near_fft_ = std::make_unique<FftConvolver>(near_, width, height);
  // Dense once the sources' direct cost exceeds half a whole-frame
  // transform's (the tiles' own cost is about the same).
  const int side = 2 * radius_ + 1;
  dense_from_ = size_t(0.5 * double(fft_size(width + radius_)) * double(fft_size(height + radius_)) / (double(side) * side));
  // Middle: K (w_1 - w_0), reaching R_1 / f1 of its pixels.
  const int reach = int(std::ceil(r1 / f1));
  ComponentKernels middle = build_component_kernels(reach + 1, reach + 1, ppd / f1, optics);
  for (cv::Mat* k : components(middle)) apply_band(*k, f1, w0, w1);
  for (cv::Mat* k : components(middle)) sharpen(*k, kMiddleSharpening);
  // Tail: K (1 - w_1), the whole frame's reach.
  ComponentKernels tail = build_component_kernels(padded_w / f2, padded_h / f2, ppd / f2, optics);
  for (cv::Mat* k : components(tail)) apply_window(*k, f2, w1, true);
  coarse_.resize(2);
  coarse_[0].factor = f1;
  coarse_[0].size = {padded_w / f1, padded_h / f1};
  coarse_[0].engine = std::make_unique<FftConvolver>(middle, padded_w / f1, padded_h / f1);
  coarse_[1].factor = f2;
  coarse_[1].size = {padded_w / f2, padded_h / f2};
  coarse_[1].engine = std::make_unique<FftConvolver>(tail);
}

SplitConvolver::~SplitConvolver() = default;

cv::Mat SplitConvolver::convolve(const cv::Mat& rgb, const ChannelWeights& w) const {
  CV_Assert(rgb.cols == width_ && rgb.rows == height_ && rgb.type() == CV_32FC3);
  cv::Mat out = spread_near(rgb, w);
  add_coarse(rgb, w, out);
  return out;
}

cv::Mat SplitConvolver::spread_near(const cv::Mat& rgb, const ChannelWeights& w) const {
  // Dense (the whole image, or many lights): by FFT (over tiles or the
  // whole frame); decided as soon as the sources' direct cost exceeds
  // half a whole-frame transform's (dense_from_).
  const int r = radius_;
  std::vector<Source> sources;  // row by row: sorted by y
  cv::Mat out;
  for (int y = 0; y < rgb.rows; ++y) {
    const cv::Vec3f* row = rgb.ptr<cv::Vec3f>(y);
    for (int x = 0; x < rgb.cols; ++x)
      if (row[x] != cv::Vec3f()) sources.push_back({x, y, row[x]});
    if (sources.size() > dense_from_) {
      if (near_tiles_)
        near_tiles_->convolve(rgb, w, out);
      else
        near_fft_->convolve(rgb, w, out);
      return out;
    }
  }
  out = cv::Mat::zeros(rgb.size(), CV_32FC3);
  cv::Mat kernel[3];
  for (int c = 0; c < 3; ++c) combined_kernel(near_, w[size_t(c)], c).convertTo(kernel[c], CV_32F);
  // Sparse: each output row gathers the sources within R rows, in order,
  // so the sums do not depend on how rows are split among threads.
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      cv::Vec3f* o = out.ptr<cv::Vec3f>(y);
      auto first = std::lower_bound(sources.begin(), sources.end(), y - r,
                                    [](const Source& s, int v) { return s.y < v; });
      for (auto s = first; s != sources.end() && s->y <= y + r; ++s) {
        const int ky = y - s->y + r;
        const int x0 = std::max(0, s->x - r), x1 = std::min(rgb.cols - 1, s->x + r);
        const float* k[3] = {kernel[0].ptr<float>(ky), kernel[1].ptr<float>(ky), kernel[2].ptr<float>(ky)};
        for (int x = x0; x <= x1; ++x) {
          const int kx = x - s->x + r;
          for (int c = 0; c < 3; ++c) o[x][c] += s->value[c] * k[c][kx];
        }
      }
    }
  });
  return out;
}

void SplitConvolver::add_coarse(const cv::Mat& rgb, const ChannelWeights& w, cv::Mat& out) const {
  const Level& middle = coarse_[0];
  const Level& tail = coarse_[1];
  // Block sums of the input at each level (zero-padded to whole tail blocks).
  const cv::Mat mid_in = block_sums(rgb, middle.factor, middle.size);
  const int step = tail.factor / middle.factor;
  const cv::Mat tail_in = block_sums(mid_in, step, tail.size);
  // The energy landing on each block, the tail's brought to the middle's
  // blocks, then both to the frame's pixels (bilinear, as cv::resize),
  // each channel's total kept: each enlargement is scaled by its input's
  // total over the total the enlargement gives it.
  cv::Mat landed = middle.engine->convolve(mid_in, w);
  const cv::Mat tail_landed = tail.engine->convolve(tail_in, w);
  const Enlargement::Totals tail_totals = tail_up_.totals(tail_landed);
  add_enlarged<false>(tail_landed, tail_up_.x, tail_up_.y, energy_scale(tail_totals.input, tail_totals.enlarged),
                      landed);
  // out = max(near + coarse, 0): rounding residue never goes negative.
  const Enlargement::Totals totals = middle_up_.totals(landed);
  add_enlarged<true>(landed, middle_up_.x, middle_up_.y, energy_scale(totals.input, totals.enlarged), out);
}

}  // namespace eyestream::glare
