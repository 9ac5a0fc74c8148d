#include "retina/area_reduction.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "retina/pixel_vector.hpp"
#include "retina/vector_clones.hpp"

namespace eyestream::retina {

namespace {

// The reduction cv::resize works with for `from` to `to` pixels: the
// reciprocal of its output-to-input ratio, as it computes it.
double input_per_output(int from, int to) { return 1.0 / (double(to) / double(from)); }

// Whether cv::resize takes its whole-factor path for this axis.
bool whole(double scale) { return std::abs(scale - double(cvRound(scale))) < DBL_EPSILON; }

// Output pixel d's sums: 0 + input pixel first[d] w_0 + the next one's
// w_1 + ..., left to right, each channel alone (the fourth lane is never
// stored). `pixels` lists the output pixels to make; every one has `taps`
// taps, so the tap loop's branch is the same for all of them. Unless
// `last`, none reads the row's last input pixel, so each tap loads four
// floats; with it, three.
template <bool last>
void row_sums(const float* __restrict in, const int* __restrict first, const float* __restrict weight,
              const int* pixels, size_t count, int taps, size_t stride, float* __restrict out) {
  for (size_t k = 0; k < count; ++k) {
    const int d = pixels[k];
    const float* p = in + 3 * size_t(first[d]);
    const float* w = weight + size_t(d) * stride;
    PixelVector sum = {0, 0, 0, 0};
    for (int t = 0; t < taps; ++t) sum = sum + (last ? three_floats(p + 3 * t) : four_floats(p + 3 * t)) * w[t];
    store_three(out + 3 * size_t(d), sum);
  }
}

EYESTREAM_VECTOR_CLONES
void first_row_term(const float* __restrict sums, float weight, float* __restrict out, int n) {
  for (int v = 0; v < n; ++v) out[v] = weight * sums[v];
}

EYESTREAM_VECTOR_CLONES
void add_row_term(const float* __restrict sums, float weight, float* __restrict out, int n) {
  for (int v = 0; v < n; ++v) out[v] = out[v] + weight * sums[v];
}

// cv::resize's whole-factor path for three-channel floats (OpenCV's
// resizeAreaFast_, which has vector code only for one or four channels;
// retina/halve_frame.hpp makes its factor 2 alone, a row at a time):
// output value = (0 + the block's values four at a time, s = s + (((a + b)
// + c) + d), in the order of its offsets (row after row, left to right),
// the rest one at a time) times 1.f / area. Here a pixel's three sums in
// one vector; the row's last pixel loads three floats, the others four.
template <bool last>
inline PixelVector block_value(const float* p, const int* offsets, int area) {
  const auto at = [&](int k) { return last ? three_floats(p + offsets[k]) : four_floats(p + offsets[k]); };
  PixelVector sum = {0, 0, 0, 0};
  int k = 0;
  for (; k <= area - 4; k += 4) sum = sum + (((at(k) + at(k + 1)) + at(k + 2)) + at(k + 3));
  for (; k < area; ++k) sum = sum + at(k);
  return sum;
}

void whole_factor_row(const float* in, const int* offsets, int area, int step_x, int pixels, float* out) {
  const float scale = 1.f / float(area);
  const PixelVector scales = {scale, scale, scale, scale};
  for (int d = 0; d + 1 < pixels; ++d)
    store_three(out + 3 * size_t(d), block_value<false>(in + size_t(d) * step_x, offsets, area) * scales);
  if (pixels > 0)
    store_three(out + 3 * size_t(pixels - 1),
                block_value<true>(in + size_t(pixels - 1) * step_x, offsets, area) * scales);
}

}  // namespace

// cv::resize's area taps (OpenCV's imgproc/resize.cpp, computeResizeAreaTab):
// output pixel d covers input [d s, d s + s), s the reduction; a partly
// covered input pixel at either end weighs its covered share, each whole
// one 1, all over the covered width (shorter at the input's end). Shares
// below 1e-3 of a pixel are dropped.
AreaReduction::Axis::Axis(int from, int to) {
  const double scale = input_per_output(from, to);
  for (int d = 0; d < to; ++d) {
    const double x1 = d * scale, x2 = x1 + scale;
    const double width = std::min(scale, from - x1);
    int s2 = std::min(int(std::floor(x2)), from - 1);
    const int s1 = std::min(int(std::ceil(x1)), s2);
    std::vector<float> w;
    int start = s1;
    if (s1 - x1 > 1e-3) {
      start = s1 - 1;
      w.push_back(float((s1 - x1) / width));
    }
    for (int s = s1; s < s2; ++s) w.push_back(float(1.0 / width));
    if (x2 - s2 > 1e-3) w.push_back(float(std::min(std::min(x2 - s2, 1.0), width) / width));
    CV_Assert(!w.empty() && start >= 0 && start + int(w.size()) <= from);
    first.push_back(start);
    count.push_back(int(w.size()));
    weight.push_back(std::move(w));
  }
}

AreaReduction::AreaReduction(cv::Size from, cv::Size to) : from_(from), to_(to) {
  CV_Assert(!from.empty() && !to.empty());
  const double sx = input_per_output(from.width, to.width), sy = input_per_output(from.height, to.height);
  if (sx < 1.0 || sy < 1.0 || from == to) return;  // cv::resize
  if (whole(sx) && whole(sy)) {
    path_ = Path::kWholeFactor;
    factor_ = {cvRound(sx), cvRound(sy)};
    CV_Assert(from.width == factor_.width * to.width && from.height == factor_.height * to.height);
    return;
  }
  // (A pixel's taps: its input pixels, at most the reduction rounded up, + 1.)
  if (!(sx < kMostTaps - 1)) return;  // cv::resize
  path_ = Path::kGeneral;
  const Axis x(from.width, to.width);
  first_ = x.first;
  weight_.assign(size_t(to.width) * kMostTaps, 0.0f);
  for (int d = 0; d < to.width; ++d) {
    const int taps = x.count[size_t(d)];
    CV_Assert(taps <= kMostTaps);
    std::copy(x.weight[size_t(d)].begin(), x.weight[size_t(d)].end(), weight_.begin() + ptrdiff_t(d) * kMostTaps);
    const bool last = x.first[size_t(d)] + taps == from.width;
    (last ? last_ : by_taps_)[size_t(taps)].push_back(d);
  }
  down_.emplace(from.height, to.height);
}

void AreaReduction::apply(const cv::Mat& in, cv::Mat& out) const {
  CV_Assert(in.size() == from_ && out.data != in.data);
  if (path_ == Path::kOpenCv || in.type() != CV_32FC3) {
    cv::resize(in, out, to_, 0, 0, cv::INTER_AREA);
    return;
  }
  out.create(to_, CV_32FC3);
  if (path_ == Path::kWholeFactor) {
    // The block's offsets from its first value, in floats, row after row.
    const size_t step = in.step1();
    std::vector<int> offsets;
    for (int sy = 0; sy < factor_.height; ++sy)
      for (int sx = 0; sx < factor_.width; ++sx) offsets.push_back(int(sy * step) + 3 * sx);
    cv::parallel_for_(cv::Range(0, to_.height), [&](const cv::Range& rows) {
      for (int y = rows.start; y < rows.end; ++y)
        whole_factor_row(in.ptr<float>(y * factor_.height), offsets.data(), int(offsets.size()), 3 * factor_.width,
                         to_.width, out.ptr<float>(y));
    });
    return;
  }
  const int n = 3 * to_.width;
  // One stripe of output rows per thread, each with a row sum buffer made
  // by the calling thread (the frame loop asks the allocator for the same
  // blocks every frame). Within a stripe an input row shared by two
  // output rows is summed once; every value is the same whatever the
  // stripes.
  const int stripes = std::max(1, std::min(to_.height, cv::getNumThreads()));
  cv::Mat sums(stripes, n, CV_32F);
  cv::parallel_for_(cv::Range(0, stripes), [&](const cv::Range& r) {
    for (int k = r.start; k < r.end; ++k) {
      float* held = sums.ptr<float>(k);
      int held_row = -1;
      const int y0 = int(int64_t(to_.height) * k / stripes), y1 = int(int64_t(to_.height) * (k + 1) / stripes);
      for (int y = y0; y < y1; ++y) {
        float* o = out.ptr<float>(y);
        for (int t = 0; t < down_->count[size_t(y)]; ++t) {
          const int row = down_->first[size_t(y)] + t;
          if (row != held_row) {
            for (int taps = 1; taps <= kMostTaps; ++taps) {
              const std::vector<int>& plain = by_taps_[size_t(taps)];
              const std::vector<int>& last = last_[size_t(taps)];
              row_sums<false>(in.ptr<float>(row), first_.data(), weight_.data(), plain.data(), plain.size(), taps,
                              kMostTaps, held);
              row_sums<true>(in.ptr<float>(row), first_.data(), weight_.data(), last.data(), last.size(), taps,
                             kMostTaps, held);
            }
            held_row = row;
          }
          const float w = down_->weight[size_t(y)][size_t(t)];
          if (t == 0)
            first_row_term(held, w, o, n);
          else
            add_row_term(held, w, o, n);
        }
      }
    }
  });
}

}  // namespace eyestream::retina
