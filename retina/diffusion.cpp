#include "retina/diffusion.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace eyestream::retina {

void diffuse(cv::Mat& m, double variance) {
  if (!(variance > 0.0)) return;
  // Beyond the grid's own size a blur is as good as uniform: capped there,
  // so even an absurd time step stays a finite kernel.
  variance = std::min(variance, double(m.rows) * m.rows + double(m.cols) * m.cols);
  if (variance > 4.0) {
    const double sigma = std::sqrt(variance);
    cv::GaussianBlur(m, m, cv::Size(0, 0), sigma, sigma, cv::BORDER_REPLICATE);
    return;
  }
  const int passes = int(std::ceil(variance / 0.5));
  const double v = variance / passes;
  const cv::Mat k = (cv::Mat_<double>(3, 1) << v / 2, 1.0 - v, v / 2);
  for (int i = 0; i < passes; ++i) cv::sepFilter2D(m, m, -1, k, k, cv::Point(-1, -1), 0.0, cv::BORDER_REPLICATE);
}

namespace {

// One three-tap pass [a, 1 - 2a, a] each way over the departure. The
// horizontal sweep reads `from` (the departure, or the state less the rest
// on the first pass) into `across`; the vertical sweep writes the next
// departure, or on the last pass the clamped state.
template <typename T>
void departure_pass(cv::Mat& state, const cv::Mat& rest, T k, const cv::Mat* departure, cv::Mat& across,
                    cv::Mat& next, T a, bool last, T hi) {
  const int rows = state.rows, n = state.cols * 3;
  const T centre = T(1) - 2 * a;
  cv::parallel_for_(cv::Range(0, rows), [&](const cv::Range& r) {
    std::vector<T> d(size_t(n) + 6);
    for (int y = r.start; y < r.end; ++y) {
      const T* s = departure ? departure->ptr<T>(y) : state.ptr<T>(y);
      const T* b = rest.ptr<T>(y);
      for (int i = 0; i < n; ++i) d[size_t(i) + 3] = departure ? s[i] : s[i] - k * b[i];
      for (int c = 0; c < 3; ++c) d[size_t(c)] = d[size_t(c) + 3], d[size_t(n + 3 + c)] = d[size_t(n + c)];
      T* o = across.ptr<T>(y);
      for (int i = 0; i < n; ++i) o[i] = a * d[size_t(i)] + centre * d[size_t(i) + 3] + a * d[size_t(i) + 6];
    }
  });
  cv::parallel_for_(cv::Range(0, rows), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y) {
      const T* up = across.ptr<T>(std::max(y - 1, 0));
      const T* mid = across.ptr<T>(y);
      const T* down = across.ptr<T>(std::min(y + 1, rows - 1));
      if (last) {
        T* o = state.ptr<T>(y);
        const T* b = rest.ptr<T>(y);
        for (int i = 0; i < n; ++i)
          o[i] = std::clamp(k * b[i] + a * up[i] + centre * mid[i] + a * down[i], T(0), hi);
      } else {
        T* o = next.ptr<T>(y);
        for (int i = 0; i < n; ++i) o[i] = a * up[i] + centre * mid[i] + a * down[i];
      }
    }
  });
}

// The horizontal sweep of departure_pass's first pass for one row: the
// row's departure state - k rest, borders replicated, three taps across.
template <typename T>
void across_row(const cv::Mat& state, const cv::Mat& rest, T k, T a, int y, T* d, T* o) {
  const int n = state.cols * 3;
  const T centre = T(1) - 2 * a;
  const T* s = state.ptr<T>(y);
  const T* b = rest.ptr<T>(y);
  for (int i = 0; i < n; ++i) d[i + 3] = s[i] - k * b[i];
  for (int c = 0; c < 3; ++c) d[c] = d[c + 3], d[n + 3 + c] = d[n + c];
  for (int i = 0; i < n; ++i) o[i] = a * d[i] + centre * d[i + 3] + a * d[i + 6];
}

// departure_pass as the only and last pass, writing the state in place
// with no grid-sized temporary: each stripe of rows keeps the horizontal
// sweep of three rows in a ring, made before the row it comes from is
// overwritten; the rows just beyond each stripe, which a neighbouring
// stripe may overwrite first, are swept beforehand. The same arithmetic
// as departure_pass, so the same bytes.
template <typename T>
void departure_pass_in_place(cv::Mat& state, const cv::Mat& rest, T k, T a, T hi) {
  const int rows = state.rows, n = state.cols * 3;
  const T centre = T(1) - 2 * a;
  // A few stripes per thread, at most 32: the rows swept beforehand stay
  // few on a machine of many threads.
  const int stripes = std::min(rows, std::min(4 * std::max(1, cv::getNumThreads()), 32));
  const auto first_row = [&](int s) { return int(std::int64_t(rows) * s / stripes); };
  // Per stripe, the sweep of the row above it and of the row below it.
  cv::Mat beyond(2 * stripes, n, state.type());
  cv::parallel_for_(cv::Range(0, stripes), [&](const cv::Range& r) {
    std::vector<T> d(size_t(n) + 6);
    for (int s = r.start; s < r.end; ++s) {
      across_row(state, rest, k, a, std::max(first_row(s) - 1, 0), d.data(), beyond.ptr<T>(2 * s));
      across_row(state, rest, k, a, std::min(first_row(s + 1), rows - 1), d.data(), beyond.ptr<T>(2 * s + 1));
    }
  });
  cv::parallel_for_(cv::Range(0, stripes), [&](const cv::Range& r) {
    std::vector<T> d(size_t(n) + 6);
    cv::Mat ring(3, n, state.type());  // from the buffer pool, whichever thread runs the stripe
    for (int s = r.start; s < r.end; ++s) {
      const int y0 = first_row(s), y1 = first_row(s + 1);
      if (y0 >= y1) continue;
      T* slot[3] = {ring.ptr<T>(0), ring.ptr<T>(1), ring.ptr<T>(2)};  // up, mid, down
      across_row(state, rest, k, a, y0, d.data(), slot[1]);
      const T* up = y0 > 0 ? beyond.ptr<T>(2 * s) : slot[1];
      for (int y = y0; y < y1; ++y) {
        const T* mid = slot[1];
        const T* down;
        if (y + 1 < y1) {
          across_row(state, rest, k, a, y + 1, d.data(), slot[2]);
          down = slot[2];
        } else {
          down = y + 1 < rows ? beyond.ptr<T>(2 * s + 1) : mid;
        }
        T* o = state.ptr<T>(y);
        const T* b = rest.ptr<T>(y);
        for (int i = 0; i < n; ++i)
          o[i] = std::clamp(k * b[i] + a * up[i] + centre * mid[i] + a * down[i], T(0), hi);
        // The ring turns: this row's sweep is the next one's up.
        std::swap(slot[0], slot[1]);
        std::swap(slot[1], slot[2]);
        up = slot[0];
      }
    }
  });
}

template <typename T>
void diffuse_departure_as(cv::Mat& state, const cv::Mat& rest, double rest_scale, double variance, double hi) {
  const int passes = int(std::ceil(variance / 0.5));
  const T a = T(variance / passes / 2);
  if (passes == 1) {
    departure_pass_in_place<T>(state, rest, T(rest_scale), a, T(hi));
    return;
  }
  cv::Mat across(state.size(), state.type()), departure[2];
  for (int p = 0; p < passes; ++p) {
    const cv::Mat* from = p == 0 ? nullptr : &departure[(p - 1) % 2];
    if (p + 1 < passes) departure[p % 2].create(state.size(), state.type());
    departure_pass<T>(state, rest, T(rest_scale), from, across, departure[p % 2], a, p + 1 == passes, T(hi));
  }
}

}  // namespace

void diffuse_departure(cv::Mat& state, const cv::Mat& rest, double rest_scale, double variance, double hi) {
  CV_Assert(state.size() == rest.size() && state.type() == rest.type() &&
            (state.type() == CV_32FC3 || state.type() == CV_64FC3));
  if (!(variance > 0.0)) return;
  variance = std::min(variance, double(state.rows) * state.rows + double(state.cols) * state.cols);
  if (variance > 4.0) {  // a Gaussian, as diffuse()
    cv::Mat d = state - rest * rest_scale;
    diffuse(d, variance);
    state = rest * rest_scale + d;
    cv::max(state, 0.0, state);
    cv::min(state, hi, state);
    return;
  }
  if (state.depth() == CV_64F)
    diffuse_departure_as<double>(state, rest, rest_scale, variance, hi);
  else
    diffuse_departure_as<float>(state, rest, rest_scale, variance, hi);
}

}  // namespace eyestream::retina
