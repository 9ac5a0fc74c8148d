#include "pipeline/geometry/bilinear_splat.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "pipeline/geometry/register_runs.hpp"
#include "retina/pixel_vector.hpp"
#include "retina/vector_clones.hpp"

namespace eyestream::pipeline {

namespace {

constexpr int kBlockRows = 32;  // plane rows per splat task

// A target row's normalised means: each sum over its weight (times the
// multiplier when given), `outside` where nothing landed.
template <typename T, int C>
void normalise_row(const cv::Vec<T, C + 1>* sums, const float* m, const cv::Scalar& outside, T* o, int cols) {
  for (int i = 0; i < cols; ++i) {
    const cv::Vec<T, C + 1>& s = sums[i];
    for (int c = 0; c < C; ++c) o[i * C + c] = s[C] > T(0) ? s[c] / s[C] * (m ? T(m[i]) : T(1)) : T(outside[c]);
  }
}

// Three float channels and the weight as one four-float vector (GCC's and
// Clang's vector extension): one division a pixel instead of three, the
// same quotients.
typedef float Quad __attribute__((vector_size(16)));

template <>
void normalise_row<float, 3>(const cv::Vec4f* sums, const float* m, const cv::Scalar& outside, float* o, int cols) {
  const float away[3] = {float(outside[0]), float(outside[1]), float(outside[2])};
  for (int i = 0; i < cols; ++i) {
    Quad s;
    std::memcpy(&s, &sums[i], sizeof s);
    if (s[3] > 0.0f) {
      Quad q = s / Quad{s[3], s[3], s[3], s[3]};
      if (m) q = q * m[i];
      o[3 * i] = q[0], o[3 * i + 1] = q[1], o[3 * i + 2] = q[2];
    } else {
      o[3 * i] = away[0], o[3 * i + 1] = away[1], o[3 * i + 2] = away[2];
    }
  }
}

// sum += value x share, each channel and the weight alone.
template <typename T, int N>
inline void add_share(cv::Vec<T, N>& sum, const cv::Vec<T, N>& value, T share) {
  sum += value * share;
}

// One image row's bilinear splat into a block's sums (each sum the
// pixel's channels and its weight): every share value x ((1 - fx or fx) x
// (1 - fy or fy)), added in the row's order.
template <typename T, int C>
void splat_row(const T* in, const cv::Vec2f* pos, int pixels, float kx, float ky, float offset, int r0, int rows,
               int cols, cv::Vec<T, C + 1>* sums) {
  using Acc = cv::Vec<T, C + 1>;
  for (int x = 0; x < pixels; ++x) {
    const float tx = pos[x][0] * kx + offset, ty = pos[x][1] * ky + offset;
    const int i0 = int(std::floor(tx)), j0 = int(std::floor(ty));
    if (j0 + 1 < r0 || j0 >= r0 + rows) continue;
    const T fx = T(tx - i0), fy = T(ty - j0);
    Acc value;
    for (int c = 0; c < C; ++c) value[c] = in[x * C + c];
    value[C] = T(1);
    for (int dj = 0; dj < 2; ++dj) {
      const int j = j0 + dj - r0;
      if (j < 0 || j >= rows) continue;
      const T wy = dj ? fy : T(1) - fy;
      for (int di = 0; di < 2; ++di) {
        const int i = i0 + di;
        if (i < 0 || i >= cols) continue;
        add_share(sums[block_cell(j, i, cols + 2)], value, (di ? fx : T(1) - fx) * wy);
      }
    }
  }
}

// The same for three float channels and the weight as one vector
// (retina/pixel_vector.hpp), held in registers along runs of pixels
// (register_runs.hpp; most pixels are in long runs: the retina's grid has
// at most a site per pixel). The same products, and each sum its terms in
// the row's order from what it held: the same bytes as the loop above.
template <>
EYESTREAM_VECTOR_CLONES void splat_row<float, 3>(const float* in, const cv::Vec2f* pos, int pixels, float kx, float ky,
                                                 float offset, int r0, int rows, int cols, cv::Vec4f* sums_in) {
  using Sum = retina::PixelVector;
  Sum* sums = reinterpret_cast<Sum*>(sums_in);  // (the block's buffer: used only as Sum, by memset and memcpy)
  const int stride = cols + 2;
  // Pixel x's four shares, or false when none of its four cells is in the
  // block's rows and the target's columns (as the loop above skips them).
  const auto shares = [&](int x, int& i0, int& j0, Sum& tl, Sum& tr, Sum& bl, Sum& br) {
    const float tx = pos[x][0] * kx + offset, ty = pos[x][1] * ky + offset;
    i0 = int(std::floor(tx));
    j0 = int(std::floor(ty));
    if (j0 + 1 < r0 || j0 >= r0 + rows || i0 < -1 || i0 >= cols) return false;
    const float fx = tx - float(i0), fy = ty - float(j0);
    Sum value = {0.0f, 0.0f, 0.0f, 1.0f};
    std::memcpy(&value, in + 3 * size_t(x), 3 * sizeof(float));
    tl = value * ((1.0f - fx) * (1.0f - fy));
    tr = value * (fx * (1.0f - fy));
    bl = value * ((1.0f - fx) * fy);
    br = value * (fx * fy);
    return true;
  };
  add_in_runs(shares, 0, pixels, sums, stride, r0);
}

// `outside` in target pixels [from, to) of a row.
template <typename T, int C>
void fill_outside(const cv::Scalar& outside, T* o, int from, int to) {
  for (int i = from; i < to; ++i)
    for (int c = 0; c < C; ++c) o[i * C + c] = T(outside[c]);
}

// Accumulates the bilinear splat of image rows [first_row, last_row] into
// the target rows [r0, r0 + kBlockRows), then writes their normalised means
// to `out` (times `multiplier` when given; `outside` where nothing lands).
// Only target columns [lo, hi) can be reached (the rows' positions
// across): the sums are kept and normalised there only; the rest of the
// block is `outside` (the retina's grid is twice the frame each way).
template <typename T, int C>
void splat_block(const cv::Mat& image, const cv::Mat& positions, SplatAffine a, int r0, int first_row, int last_row,
                 int lo, int hi, const cv::Scalar& outside, const cv::Mat& multiplier, cv::Vec<T, C + 1>* sums,
                 cv::Mat& out) {
  using Acc = cv::Vec<T, C + 1>;
  const int rows = std::min(kBlockRows, out.rows - r0), cols = out.cols;
  if (last_row < first_row || lo >= hi) {  // nothing lands on the block: all outside
    for (int j = 0; j < rows; ++j) fill_outside<T, C>(outside, out.ptr<T>(r0 + j), 0, cols);
    return;
  }
  // Zeros (all bits clear) in the columns the block's footprints reach,
  // with a border row and column each way (register_runs.hpp's
  // block_cell), so that every footprint meeting the block has its four
  // cells (the borders' are left out).
  for (int j = -1; j <= rows; ++j)
    std::memset(static_cast<void*>(sums + block_cell(j, lo - 1, cols + 2)), 0, sizeof(Acc) * size_t(hi - lo + 2));
  const float kx = float(a.kx), ky = float(a.ky), offset = float(a.offset);
  for (int y = first_row; y <= last_row; ++y)
    splat_row<T, C>(image.ptr<T>(y), positions.ptr<cv::Vec2f>(y), image.cols, kx, ky, offset, r0, rows, cols, sums);
  for (int j = 0; j < rows; ++j) {
    T* o = out.ptr<T>(r0 + j);
    const float* m = multiplier.empty() ? nullptr : multiplier.ptr<float>(r0 + j) + lo;
    fill_outside<T, C>(outside, o, 0, lo);
    normalise_row<T, C>(sums + block_cell(j, lo, cols + 2), m, outside, o + size_t(lo) * C, hi - lo);
    fill_outside<T, C>(outside, o, hi, cols);
  }
}

// Splats `image` onto `out` in blocks of target rows, each block a task
// that scans only the image rows reaching it: the sums at each target
// pixel come in one order whatever the thread count.
template <typename T, int C>
void splat_rows(const cv::Mat& image, const cv::Mat& positions, SplatAffine a, const cv::Scalar& outside,
                const cv::Mat& multiplier, cv::Mat& out) {
  // Each image row's reach: the target rows [top, bottom] its footprints
  // can touch, and the columns [left, right), from the footprints' own
  // top rows and left columns (splat_row's arithmetic, in float: the same
  // floors; until the sixteenth session the rows were mapped in double,
  // which could leave out a share of a float rounding on a block's edge).
  std::vector<int> top(size_t(image.rows)), bottom(size_t(image.rows)), left(size_t(image.rows)),
      right(size_t(image.rows));
  const float kx = float(a.kx), ky = float(a.ky), offset = float(a.offset);
  cv::parallel_for_(cv::Range(0, image.rows), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y) {
      const cv::Vec2f* pos = positions.ptr<cv::Vec2f>(y);
      float low = 1e30f, high = -1e30f, west = 1e30f, east = -1e30f;
      for (int x = 0; x < image.cols; ++x) {
        const float tx = pos[x][0] * kx + offset, ty = pos[x][1] * ky + offset;
        low = std::min(low, ty);
        high = std::max(high, ty);
        west = std::min(west, tx);
        east = std::max(east, tx);
      }
      top[size_t(y)] = int(std::floor(low));
      bottom[size_t(y)] = int(std::floor(high)) + 1;
      left[size_t(y)] = int(std::floor(west));
      right[size_t(y)] = int(std::floor(east)) + 2;
    }
  });
  const int blocks = (out.rows + kBlockRows - 1) / kBlockRows;
  // One accumulator per share of the blocks, made here, not per thread as
  // a thread first comes: the frame loop then asks the allocator for the
  // same blocks every frame, whichever threads run (the pool has them).
  const int shares = std::min(blocks, std::max(1, cv::getNumThreads()));
  std::vector<cv::Mat> accumulators(static_cast<size_t>(shares));
  for (cv::Mat& m : accumulators) m.create(kBlockRows + 2, int(sizeof(cv::Vec<T, C + 1>)) * (out.cols + 2), CV_8U);
  cv::parallel_for_(cv::Range(0, shares), [&](const cv::Range& r) {
    for (int k = r.start; k < r.end; ++k)
    for (int b = k; b < blocks; b += shares) {
      const int r0 = b * kBlockRows, r1 = std::min(out.rows, r0 + kBlockRows);
      int first = image.rows, last = -1, lo = out.cols, hi = 0;
      for (int y = 0; y < image.rows; ++y) {
        if (bottom[size_t(y)] < r0 || top[size_t(y)] >= r1) continue;
        first = std::min(first, y);
        last = std::max(last, y);
        lo = std::min(lo, std::max(left[size_t(y)], 0));
        hi = std::max(hi, std::min(right[size_t(y)], out.cols));
      }
      splat_block<T, C>(image, positions, a, r0, first, last, lo, hi, outside, multiplier,
                        accumulators[size_t(k)].ptr<cv::Vec<T, C + 1>>(), out);
    }
  });
}

}  // namespace

cv::Mat bilinear_splat(const cv::Mat& image, const cv::Mat& positions, SplatAffine a, cv::Size size,
                       const cv::Scalar& outside, const cv::Mat& multiplier) {
  CV_Assert(positions.type() == CV_32FC2 && positions.size() == image.size());
  cv::Mat out(size, image.type());
  switch (image.type()) {
    case CV_32FC1: splat_rows<float, 1>(image, positions, a, outside, multiplier, out); break;
    case CV_32FC3: splat_rows<float, 3>(image, positions, a, outside, multiplier, out); break;
    case CV_64FC3: splat_rows<double, 3>(image, positions, a, outside, multiplier, out); break;
    default: CV_Error(cv::Error::StsUnsupportedFormat, "splat: CV_32FC1, CV_32FC3 or CV_64FC3");
  }
  return out;
}

}  // namespace eyestream::pipeline
