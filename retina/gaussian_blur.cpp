#include "retina/gaussian_blur.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "retina/vector_clones.hpp"

namespace eyestream::retina {

namespace {

// The sweeps are compiled for AVX-512 and AVX2 beside the baseline (vector_clones.hpp).

// Eight floats as one vector (GCC's vector extension: one AVX register,
// two SSE ones), loaded from and stored to any float.
// (Passed by reference, not by value: no vector crosses a call.)
typedef float Lanes __attribute__((vector_size(32)));
inline void load_lanes(Lanes& v, const float* p) { std::memcpy(&v, p, sizeof v); }
inline void store_lanes(float* p, const Lanes& v) { std::memcpy(p, &v, sizeof v); }

// Samples summed at once: four vectors of sums, held in registers over
// every tap. Each sum takes its terms in the same order as a tap-by-tap
// sweep of the whole row (the same bytes), without the row's store and
// reload at every tap.
constexpr int kBlock = 32;

// The sums of kBlock samples: w[0] centre + w[t] (before_t + after_t), tap
// t's neighbours being t pixels before and after (row) or rows[-t] and
// rows[t] (column), added one tap at a time.
struct Block {
  Lanes sum[4];
  void start(float w0, const float* centre) {
    for (int k = 0; k < 4; ++k) {
      load_lanes(sum[k], centre + 8 * k);
      sum[k] = w0 * sum[k];
    }
  }
  void add(float wt, const float* before, const float* after) {
    for (int k = 0; k < 4; ++k) {
      Lanes a, b;
      load_lanes(a, before + 8 * k);
      load_lanes(b, after + 8 * k);
      sum[k] += wt * (a + b);
    }
  }
  void store(float* out) const {
    for (int k = 0; k < 4; ++k) store_lanes(out + 8 * k, sum[k]);
  }
};

// out[i] = sum_t w[t] (in[i - t c] + in[i + t c]) over the row's interior
// samples; the r pixels at each end read replicated border pixels.
EYESTREAM_VECTOR_CLONES
void blur_row(const float* in, float* out, int width, int channels, const std::vector<float>& w) {
  const int r = int(w.size()) - 1;
  const int lo = std::min(r, width) * channels, hi = std::max(lo, (width - r) * channels);
  int i0 = lo;
  for (; i0 + kBlock <= hi; i0 += kBlock) {
    const float* at = in + i0;
    Block b;
    b.start(w[0], at);
    for (int t = 1; t <= r; ++t) b.add(w[size_t(t)], at - t * channels, at + t * channels);
    b.store(out + i0);
  }
  for (int i = i0; i < hi; ++i) out[i] = w[0] * in[i];
  for (int t = 1; t <= r; ++t) {
    const float wt = w[size_t(t)];
    const int s = t * channels;
    for (int i = i0; i < hi; ++i) out[i] += wt * (in[i - s] + in[i + s]);
  }
  const auto edge = [&](int x) {
    for (int c = 0; c < channels; ++c) {
      float acc = w[0] * in[x * channels + c];
      for (int t = 1; t <= r; ++t) {
        const int a = std::max(x - t, 0), b = std::min(x + t, width - 1);
        acc += w[size_t(t)] * (in[a * channels + c] + in[b * channels + c]);
      }
      out[x * channels + c] = acc;
    }
  };
  for (int x = 0; x < lo / channels; ++x) edge(x);
  for (int x = hi / channels; x < width; ++x) edge(x);
}

// out = w[0] rows[0] + sum_t w[t] (rows[-t] + rows[t]) over n samples;
// rows[t] is the row t below the output's (negative: above).
EYESTREAM_VECTOR_CLONES
void blur_column(const float* const* rows, float* out, int n, const std::vector<float>& w) {
  const int r = int(w.size()) - 1;
  const float* centre = rows[0];
  int i0 = 0;
  for (; i0 + kBlock <= n; i0 += kBlock) {
    Block b;
    b.start(w[0], centre + i0);
    for (int t = 1; t <= r; ++t) b.add(w[size_t(t)], rows[-t] + i0, rows[t] + i0);
    b.store(out + i0);
  }
  for (int i = i0; i < n; ++i) out[i] = w[0] * centre[i];
  for (int t = 1; t <= r; ++t) {
    const float wt = w[size_t(t)];
    const float* up = rows[-t];
    const float* down = rows[t];
    for (int i = i0; i < n; ++i) out[i] += wt * (up[i] + down[i]);
  }
}

}  // namespace

void gaussian_blur(const cv::Mat& src, cv::Mat& dst, double sigma, const std::function<void(int row)>& source_row_read) {
  CV_Assert(src.depth() == CV_32F && sigma > 0.0);
  const int ksize = cvRound(sigma * 8 + 1) | 1;
  const cv::Mat k = cv::getGaussianKernel(ksize, sigma, CV_64F);
  const int r = ksize / 2;
  std::vector<float> w(size_t(r) + 1);
  for (int t = 0; t <= r; ++t) w[size_t(t)] = float(k.at<double>(r + t));
  const int rows = src.rows, cols = src.cols, channels = src.channels(), n = cols * channels;
  // In place, the source rows a stripe reads would be overwritten by its
  // neighbour: read from a copy then.
  cv::Mat input = src.data == dst.data ? src.clone() : src;
  dst.create(src.size(), src.type());
  // A few stripes per thread: each keeps a ring of the 2r + 1 rows blurred
  // across that its next output row reads (row j in slot j mod 2r + 1).
  // The rings are made here, one per stripe, not in the stripes as threads
  // take them, so the frame loop asks the program's buffer pool for the
  // same blocks every frame whichever threads run (it has them).
  const int span = 2 * r + 1;
  const int stripes = std::min(rows, std::max(1, cv::getNumThreads()) * 2);
  std::vector<cv::Mat> rings(static_cast<size_t>(stripes));
  for (cv::Mat& ring : rings) ring.create(span, n, CV_32F);
  cv::parallel_for_(cv::Range(0, stripes), [&](const cv::Range& shares) {
    std::vector<const float*> rows_at(static_cast<size_t>(span));
    for (int k = shares.start; k < shares.end; ++k) {
      const cv::Range range(int(int64_t(rows) * k / stripes), int(int64_t(rows) * (k + 1) / stripes));
      cv::Mat& ring = rings[size_t(k)];
      const auto slot = [&](int j) { return ring.ptr<float>((j - range.start + span) % span); };
      const auto fill = [&](int j) {
        blur_row(input.ptr<float>(std::clamp(j, 0, rows - 1)), slot(j), cols, channels, w);
        // Each row once: by the stripe it belongs to (the rows a stripe
        // reads beyond its own, or replicated at the border, are another's).
        if (source_row_read && j >= range.start && j < range.end) source_row_read(j);
      };
      for (int j = range.start - r; j < range.start + r; ++j) fill(j);
      for (int y = range.start; y < range.end; ++y) {
        fill(y + r);
        for (int t = -r; t <= r; ++t) rows_at[size_t(t + r)] = slot(y + t);
        blur_column(&rows_at[size_t(r)], dst.ptr<float>(y), n, w);
      }
    }
  });
}

}  // namespace eyestream::retina
