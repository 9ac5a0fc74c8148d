#include "pipeline/geometry/fixed_splat.hpp"

#include <algorithm>
#include <cmath>

#include "pipeline/geometry/register_runs.hpp"
#include "retina/pixel_vector.hpp"
#include "retina/vector_clones.hpp"

namespace eyestream::pipeline {

namespace {

constexpr int kBlockRows = 32;  // plane rows per task

// The top row of a position's bilinear footprint (the plane row whose
// centre is at or above it). Positions are >= -0.5, so truncation floors
// y + 0.5.
inline int row_above(float y) { return int(y + 0.5f) - 1; }

// A pixel's three channels and an unused fourth, as one vector
// (retina/pixel_vector.hpp), so that each of the four bilinear shares is
// one multiply and one add.
using Rgbx = retina::PixelVector;

// One run's pixels splatted into the accumulators `sums` (row stride
// `stride`, the block's first row r0), held in registers along the run
// (register_runs.hpp).
template <bool kOnes>
EYESTREAM_VECTOR_CLONES void splat_run(const cv::Vec2f* pos, const float* in, int x, int end, Rgbx* sums, int stride,
                                       int r0) {
  const auto shares = [&](int at, int& i0, int& j0, Rgbx& tl, Rgbx& tr, Rgbx& bl, Rgbx& br) {
    const float tx = pos[at][0] + 0.5f, ty = pos[at][1] + 0.5f;
    i0 = int(tx) - 1;
    j0 = int(ty) - 1;
    const float fx = tx - float(i0 + 1), fy = ty - float(j0 + 1);
    Rgbx value = {1.0f, 1.0f, 1.0f, 0.0f};
    if constexpr (!kOnes) value = Rgbx{in[3 * size_t(at)], in[3 * size_t(at) + 1], in[3 * size_t(at) + 2], 0.0f};
    const Rgbx top_row = value * (1.0f - fy), bottom_row = value * fy;
    tl = top_row * (1.0f - fx);
    tr = top_row * fx;
    bl = bottom_row * (1.0f - fx);
    br = bottom_row * fx;
    return true;
  };
  add_in_runs(shares, x, end, sums, stride, r0);
}

// A plane row out of its sums: each pixel's three values times its
// factor. Four floats are stored at once, the fourth being the next
// pixel's first, which that pixel then writes; the last pixel three.
EYESTREAM_VECTOR_CLONES void scaled_row(const Rgbx* sums, const float* factor, float* out, int cols) {
  int i = 0;
  for (; i + 1 < cols; ++i) retina::store_four(out + 3 * size_t(i), sums[i] * factor[i]);
  if (i < cols) retina::store_three(out + 3 * size_t(i), sums[i] * factor[i]);
}

}  // namespace

FixedSplat::FixedSplat(const cv::Mat& positions, cv::Size plane) : positions_(positions), plane_(plane) {
  CV_Assert(positions.type() == CV_32FC2 && !plane.empty());
  const int blocks = (plane.height + kBlockRows - 1) / kBlockRows;
  // The plane rows each frame row reaches at most; every position where
  // the accumulators' border column and row each way hold its footprint
  // (a footprint below the plane falls in no block).
  std::vector<int> top(size_t(positions.rows)), bottom(size_t(positions.rows));
  for (int y = 0; y < positions.rows; ++y) {
    float low = 1e30f, high = -1e30f;
    const cv::Vec2f* pos = positions.ptr<cv::Vec2f>(y);
    for (int x = 0; x < positions.cols; ++x) {
      CV_Assert(pos[x][0] >= -0.5f && pos[x][0] < float(plane.width) + 0.5f && pos[x][1] >= -0.5f &&
                pos[x][1] < 1e8f);
      low = std::min(low, pos[x][1]);
      high = std::max(high, pos[x][1]);
    }
    top[size_t(y)] = int(std::floor(low - 0.5f));
    bottom[size_t(y)] = int(std::floor(high - 0.5f)) + 1;
  }
  // Each block's runs: the pixels, of the frame rows that can reach the
  // block, whose footprint's rows j0, j0 + 1 meet the block's rows
  // [r0, r0 + rows).
  std::vector<std::vector<Run>> per_block(static_cast<size_t>(blocks));
  cv::parallel_for_(cv::Range(0, blocks), [&](const cv::Range& r) {
    for (int b = r.start; b < r.end; ++b) {
      const int r0 = b * kBlockRows, rows = std::min(kBlockRows, plane.height - r0);
      std::vector<Run>& runs = per_block[size_t(b)];
      for (int y = 0; y < positions.rows; ++y) {
        if (bottom[size_t(y)] < r0 || top[size_t(y)] >= r0 + rows) continue;
        const cv::Vec2f* pos = positions.ptr<cv::Vec2f>(y);
        int start = -1;
        for (int x = 0; x <= positions.cols; ++x) {
          bool in = false;
          if (x < positions.cols) {
            const int j0 = row_above(pos[x][1]);
            in = j0 + 1 >= r0 && j0 < r0 + rows;
          }
          if (in && start < 0) start = x;
          if (!in && start >= 0) {
            runs.push_back({y, start, x});
            start = -1;
          }
        }
      }
    }
  });
  first_run_.push_back(0);
  for (const std::vector<Run>& runs : per_block) {
    runs_.insert(runs_.end(), runs.begin(), runs.end());
    first_run_.push_back(runs_.size());
  }
}

void FixedSplat::apply(const cv::Mat& frame, const cv::Mat& factor, cv::Mat& out) const {
  CV_Assert(frame.type() == CV_32FC3 && frame.size() == positions_.size() && factor.type() == CV_32F &&
            factor.size() == plane_);
  out.create(plane_, CV_32FC3);
  splat<false>(&frame, &factor, out);
}

void FixedSplat::weight_sums(cv::Mat& out) const {
  out.create(plane_, CV_32F);
  splat<true>(nullptr, nullptr, out);
}

template <bool kOnes>
void FixedSplat::splat(const cv::Mat* frame, const cv::Mat* factor, cv::Mat& out) const {
  const int cols = plane_.width, stride = cols + 2;
  const int blocks = int(first_run_.size()) - 1;
  // One accumulator per share of the blocks, made by the calling thread,
  // share k taking blocks k, k + shares, ...: the frame loop asks the
  // allocator for the same blocks every frame, whichever threads run. Each
  // accumulator has a border row and column each way (no bounds checks).
  const int shares = std::min(blocks, std::max(1, cv::getNumThreads()));
  std::vector<cv::Mat> accumulators(static_cast<size_t>(shares));
  for (cv::Mat& m : accumulators) m.create(kBlockRows + 2, stride, CV_32FC4);  // Rgbx, 16-byte aligned
  cv::parallel_for_(cv::Range(0, shares), [&](const cv::Range& r) {
    for (int k = r.start; k < r.end; ++k)
      for (int b = k; b < blocks; b += shares) {
        Rgbx* sums = reinterpret_cast<Rgbx*>(accumulators[size_t(k)].ptr<float>());
        const int r0 = b * kBlockRows, rows = std::min(kBlockRows, plane_.height - r0);
        std::fill(sums, sums + size_t(rows + 2) * size_t(stride), Rgbx{0, 0, 0, 0});  // rows r0 - 1 .. r0 + rows
        for (size_t i = first_run_[size_t(b)]; i < first_run_[size_t(b) + 1]; ++i) {
          const Run& run = runs_[i];
          const float* in = kOnes ? nullptr : frame->ptr<float>(run.y);
          splat_run<kOnes>(positions_.ptr<cv::Vec2f>(run.y), in, run.x0, run.x1, sums, stride, r0);
        }
        for (int j = 0; j < rows; ++j) {
          const Rgbx* s = &sums[block_cell(j, 0, stride)];
          if (kOnes) {  // (a factor of 1 would change nothing)
            float* o = out.ptr<float>(r0 + j);
            for (int i = 0; i < cols; ++i) o[i] = s[i][0];
            continue;
          }
          scaled_row(s, factor->ptr<float>(r0 + j), out.ptr<float>(r0 + j), cols);
        }
      }
  });
}

}  // namespace eyestream::pipeline
