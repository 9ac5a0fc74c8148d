#include "glare/split_convolver.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace eyestream::glare {

namespace {

constexpr double kHaloOuterDeg = 4.5;  // Spencer et al. 1995: the halo ring's outer edge

// The near window w(r) for r in full-resolution pixels.
double near_window(double r, double radius) {
  const double inner = radius / 2.0;
  if (r <= inner) return 1.0;
  if (r >= radius) return 0.0;
  return (radius - r) / (radius - inner);
}

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
void apply_window(cv::Mat& kernel, double pixel_scale, double radius, bool complement) {
  const double cx = kernel.cols / 2, cy = kernel.rows / 2;
  for (int y = 0; y < kernel.rows; ++y) {
    double* row = kernel.ptr<double>(y);
    for (int x = 0; x < kernel.cols; ++x) {
      const double w = near_window(std::hypot(x - cx, y - cy) * pixel_scale, radius);
      row[x] *= complement ? 1.0 - w : w;
    }
  }
}

// Multiplies `kernel` (centred) by window(r, outer) - window(r, inner),
// r = the distance in full-resolution pixels (pixel_scale per kernel pixel).
void apply_band(cv::Mat& kernel, double pixel_scale, double inner, double outer) {
  const double cx = kernel.cols / 2, cy = kernel.rows / 2;
  for (int y = 0; y < kernel.rows; ++y) {
    double* row = kernel.ptr<double>(y);
    for (int x = 0; x < kernel.cols; ++x) {
      const double r = std::hypot(x - cx, y - cy) * pixel_scale;
      row[x] *= near_window(r, outer) - near_window(r, inner);
    }
  }
}

// `m` (energies per block of a level) enlarged by `by` to `size`, as
// energies per pixel of that size: bilinear, then each channel scaled so
// its total is kept.
cv::Mat enlarge_keeping_energy(const cv::Mat& m, int by, cv::Size size) {
  cv::Mat up;
  cv::resize(m * (1.0 / (double(by) * by)), up, size, 0, 0, cv::INTER_LINEAR);
  const cv::Scalar want = cv::sum(m), got = cv::sum(up);
  cv::Scalar scale;
  for (int c = 0; c < 3; ++c) scale[c] = got[c] > 0 ? want[c] / got[c] : 0.0;
  cv::multiply(up, scale, up);
  return up;
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

}  // namespace

SplitConvolver::SplitConvolver(int width, int height, double ppd, int factor, const EyeOptics& optics,
                               bool with_centre)
    : width_(width), height_(height), factor_(std::max(factor, 2)), radius_(8 * factor_) {
  const int f1 = factor_, f2 = 4 * factor_;
  const int padded_w = (width + f2 - 1) / f2 * f2, padded_h = (height + f2 - 1) / f2 * f2;
  // Window radii in full-resolution pixels. The tail starts beyond the
  // lenticular halo (rings up to 4.5 deg, coloured at a scale its blocks
  // would blur) and where its blocks are small against the PSF's change.
  const double r0 = radius_, r1 = std::max(16.0 * f2, 2.0 * kHaloOuterDeg * ppd);
  near_ = build_component_kernels(radius_ + 1, radius_ + 1, ppd, optics);
  for (cv::Mat* k : components(near_)) {
    apply_window(*k, 1.0, r0, false);
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
  for (cv::Mat* k : components(middle)) apply_band(*k, f1, r0, r1);
  for (cv::Mat* k : components(middle)) sharpen(*k, kMiddleSharpening);
  // Tail: K (1 - w_1), the whole frame's reach.
  ComponentKernels tail = build_component_kernels(padded_w / f2, padded_h / f2, ppd / f2, optics);
  for (cv::Mat* k : components(tail)) apply_window(*k, f2, r1, true);
  coarse_.resize(2);
  coarse_[0].factor = f1;
  coarse_[0].size = {padded_w / f1, padded_h / f1};
  coarse_[0].engine = std::make_unique<FftConvolver>(middle, padded_w / f1, padded_h / f1);
  coarse_[1].factor = f2;
  coarse_[1].size = {padded_w / f2, padded_h / f2};
  coarse_[1].engine = std::make_unique<FftConvolver>(tail);
  // Enlarging the middle level to the padded frame: each frame pixel's taps,
  // and the weight each block gets over the whole padded frame.
  up_x_ = linear_taps(0, padded_w, 1.0 / f1, padded_w / f1);
  up_y_ = linear_taps(0, padded_h, 1.0 / f1, padded_h / f1);
  up_column_weight_.assign(size_t(padded_w / f1), 0.0);
  up_row_weight_.assign(size_t(padded_h / f1), 0.0);
  for (const LinearTap& t : up_x_) up_column_weight_[size_t(t.a)] += 1.0 - t.wb, up_column_weight_[size_t(t.b)] += t.wb;
  for (const LinearTap& t : up_y_) up_row_weight_[size_t(t.a)] += 1.0 - t.wb, up_row_weight_[size_t(t.b)] += t.wb;
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
  // blocks, then both to the frame's pixels (bilinear, as cv::resize), each
  // channel's total kept.
  cv::Mat landed = middle.engine->convolve(mid_in, w);
  landed += enlarge_keeping_energy(tail.engine->convolve(tail_in, w), step, middle.size);
  cv::Vec3d got;  // the enlargement's totals: each block times the weight the frame's pixels give it
  for (int v = 0; v < landed.rows; ++v) {
    const cv::Vec3f* m = landed.ptr<cv::Vec3f>(v);
    cv::Vec3d row;
    for (int u = 0; u < landed.cols; ++u) row += cv::Vec3d(m[u]) * up_column_weight_[size_t(u)];
    got += row * up_row_weight_[size_t(v)];
  }
  const cv::Scalar want = cv::sum(landed);
  float scale[3];
  for (int c = 0; c < 3; ++c) scale[c] = got[c] > 0 ? float(want[c] / got[c]) : 0.0f;
  // out = max(near + coarse, 0): rounding residue never goes negative.
  // Each stripe widens a block row once for all the frame rows that read
  // it (the same sums as per pixel, so the same bytes).
  cv::parallel_for_(
      cv::Range(0, height_),
      [&](const cv::Range& rows) {
        cv::Mat widened(2, width_, CV_32FC3);  // two block rows across the frame, in slots row % 2
        int held[2] = {-1, -1};
        const auto row_of = [&](int v) {
          cv::Vec3f* wide = widened.ptr<cv::Vec3f>(v % 2);
          if (held[v % 2] != v) {
            const cv::Vec3f* m = landed.ptr<cv::Vec3f>(v);
            for (int x = 0; x < width_; ++x) {
              const LinearTap& tx = up_x_[size_t(x)];
              wide[x] = m[tx.a] * (1.0f - tx.wb) + m[tx.b] * tx.wb;
            }
            held[v % 2] = v;
          }
          return wide;
        };
        for (int y = rows.start; y < rows.end; ++y) {
          cv::Vec3f* o = out.ptr<cv::Vec3f>(y);
          const LinearTap& ty = up_y_[size_t(y)];
          const cv::Vec3f* top = row_of(ty.a);
          const cv::Vec3f* bottom = ty.b == ty.a ? top : row_of(ty.b);
          for (int x = 0; x < width_; ++x) {
            const cv::Vec3f u = top[x] * (1.0f - ty.wb) + bottom[x] * ty.wb;
            for (int c = 0; c < 3; ++c) o[x][c] = std::max(o[x][c] + u[c] * scale[c], 0.0f);
          }
        }
      },
      double(std::max(1, cv::getNumThreads()) * 4));
}

}  // namespace eyestream::glare
