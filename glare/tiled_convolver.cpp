#include "glare/tiled_convolver.hpp"

#include <fftw3.h>


#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <vector>

#include "glare/channel_rows.hpp"
#include "glare/fftw_planner.hpp"
#include "glare/kernel_spectra.hpp"
#include "glare/vector_clones.hpp"

namespace eyestream::glare {

int tile_size_for(int radius) {
  const auto cost = [&](int t) {
    const double b = t - 2.0 * radius;
    return b < 1.0 ? HUGE_VAL : double(t) * t * std::log2(double(t) * t) / (b * b);
  };
  int best = 0;
  for (int t = 64; t <= 512; t *= 2) {
    if (t == 512 && 2 * (256 - 2 * radius) >= 256) break;  // 256 keeps half its window: stay in cache
    if (best == 0 || cost(t) < cost(best)) best = t;
  }
  // A larger tile while the chosen one leaves less than a quarter of its
  // side as output (reaches of 193 px or more).
  while (cost(best) == HUGE_VAL || best - 2 * radius < best / 4) best *= 2;
  return best;
}

double tile_output_share(int radius) {
  const int t = tile_size_for(radius);
  const double s = double(t - 2 * radius) / t;
  return s * s;
}

namespace {

// The per-pixel loops are compiled for AVX-512 and AVX2 beside the
// baseline (glare/vector_clones.hpp: no FMA, so every version gives the
// same bytes).

// Whether any of a channel's window values is not 0: by blocks, stopping
// at the first lit one.
EYESTREAM_VECTOR_CLONES
bool any_light(const double* real, size_t n) {
  constexpr size_t kBlock = 256;
  for (size_t j0 = 0; j0 < n; j0 += kBlock) {
    int any = 0;
    for (size_t j = j0; j < std::min(j0 + kBlock, n); ++j) any |= real[j] != 0.0;
    if (any) return true;
  }
  return false;
}

// A spectrum times a real one, in place.
EYESTREAM_VECTOR_CLONES
void multiply_spectrum(double* spectrum, const double* kernel, size_t n) {
  for (size_t j = 0; j < n; ++j) {
    spectrum[2 * j] *= kernel[j];
    spectrum[2 * j + 1] *= kernel[j];
  }
}

// out = w0 k0 + w1 k1 + w2 k2 + w3 k3 over n values.
EYESTREAM_VECTOR_CLONES
void combine_spectra(const double* const k[4], const double w[4], size_t n, double* out) {
  for (size_t j = 0; j < n; ++j) out[j] = w[0] * k[0][j] + w[1] * k[1][j] + w[2] * k[2][j] + w[3] * k[3][j];
}

}  // namespace

// One share of the tiles' arrays for their transforms (each channel's
// window, then its result, and one spectrum), made by the calling thread
// the first time a frame is split into that many shares and kept with the
// engine: the frame loop asks the allocator for nothing, whichever threads
// run the shares.
struct TileArrays {
  double* real[3] = {};
  fftw_complex* spectrum = nullptr;
  TileArrays(int t, size_t n) {
    for (double*& r : real) r = fftw_alloc_real(size_t(t) * t);
    spectrum = fftw_alloc_complex(n);
  }
  ~TileArrays() {
    for (double* r : real) fftw_free(r);
    fftw_free(spectrum);
  }
  TileArrays(const TileArrays&) = delete;
  TileArrays& operator=(const TileArrays&) = delete;
};

struct TiledConvolver::Engine {
  int width = 0, height = 0, radius = 0, t = 0, block = 0, half = 0;
  std::vector<double> spectra[6];  // core, inner, outer, halo R, G, B: real parts, t x (t / 2 + 1)
  std::vector<double> combined;    // this frame's spectrum of each channel's kernel, 3 t (t / 2 + 1)
  std::vector<std::unique_ptr<TileArrays>> shares;  // one per share of a frame's tiles
  fftw_plan forward = nullptr, backward = nullptr;
};

TiledConvolver::TiledConvolver(const ComponentKernels& k, int width, int height) : engine_(std::make_unique<Engine>()) {
  Engine& e = *engine_;
  CV_Assert(k.core.rows == k.core.cols && k.core.cols % 2 == 1 && width > 0 && height > 0);
  e.width = width;
  e.height = height;
  e.radius = k.core.cols / 2;
  e.t = tile_size_for(e.radius);
  e.block = e.t - 2 * e.radius;
  e.half = e.t / 2 + 1;
  const size_t n = size_t(e.t) * e.half;
  e.combined.resize(3 * n);
  kernel_spectra({&k.core, &k.inner, &k.outer, &k.halo[0], &k.halo[1], &k.halo[2]}, e.t, e.t,
                 [&](int i, const double (*s)[2]) {
                   std::vector<double>& out = e.spectra[i];
                   out.resize(n);
                   for (size_t j = 0; j < n; ++j) out[j] = s[j][0];
                 });
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  double* real = fftw_alloc_real(size_t(e.t) * e.t);
  fftw_complex* spectrum = fftw_alloc_complex(n);
  e.forward = make_fftw_plan([&](unsigned flags) { return fftw_plan_dft_r2c_2d(e.t, e.t, real, spectrum, flags); });
  e.backward = make_fftw_plan([&](unsigned flags) { return fftw_plan_dft_c2r_2d(e.t, e.t, spectrum, real, flags); });
  fftw_free(real);
  fftw_free(spectrum);
}

TiledConvolver::~TiledConvolver() {
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  fftw_destroy_plan(engine_->forward);
  fftw_destroy_plan(engine_->backward);
}

int TiledConvolver::tile_size() const { return engine_->t; }

void TiledConvolver::convolve(const cv::Mat& rgb, const ChannelWeights& w, cv::Mat& out) const {
  Engine& e = *engine_;
  CV_Assert(rgb.type() == CV_32FC3 && rgb.cols == e.width && rgb.rows == e.height);
  out.create(rgb.size(), CV_32FC3);
  const int t = e.t, r = e.radius, b = e.block;
  const size_t n = size_t(t) * e.half;
  // Each channel's combined kernel spectrum for this frame's weights.
  std::vector<double>& kernel = e.combined;
  for (int c = 0; c < 3; ++c) {
    const double weights[4] = {w[size_t(c)].core, w[size_t(c)].inner, w[size_t(c)].outer, w[size_t(c)].halo};
    const double* spectra[4] = {e.spectra[0].data(), e.spectra[1].data(), e.spectra[2].data(), e.spectra[3 + c].data()};
    combine_spectra(spectra, weights, n, kernel.data() + size_t(c) * n);
  }
  const int across = (e.width + b - 1) / b, down = (e.height + b - 1) / b;
  const double scale = 1.0 / (double(t) * t);
  // The tiles in as many shares as threads, share k taking tiles k,
  // k + shares, ...: each share has its own arrays.
  const int tiles = across * down, shares = std::min(tiles, std::max(1, cv::getNumThreads()));
  while (int(e.shares.size()) < shares) e.shares.push_back(std::make_unique<TileArrays>(t, n));
  cv::parallel_for_(cv::Range(0, shares), [&](const cv::Range& range) {
    for (int k = range.start; k < range.end; ++k)
    for (int tile = k; tile < tiles; tile += shares) {
      TileArrays& a = *e.shares[size_t(k)];
      fftw_complex* spectrum = a.spectrum;
      // Output block [x0, x0 + b) x [y0, y0 + b) of the frame, read from
      // the window r pixels wider each way, every channel in one sweep; a
      // window cut by the frame's edge is zero beyond it.
      const int x0 = (tile % across) * b, y0 = (tile / across) * b;
      const int wx0 = std::max(x0 - r, 0), wx1 = std::min(x0 + b + r, e.width);
      const int wy0 = std::max(y0 - r, 0), wy1 = std::min(y0 + b + r, e.height);
      const int ox1 = std::min(x0 + b, e.width), oy1 = std::min(y0 + b, e.height);
      if (wx1 - wx0 < t || wy1 - wy0 < t)
        for (double* real : a.real) std::memset(real, 0, sizeof(double) * size_t(t) * t);
      for (int y = wy0; y < wy1; ++y) {
        const size_t at = size_t(y - y0 + r) * t + size_t(wx0 - x0 + r);
        split_row(rgb.ptr<float>(y) + 3 * wx0, wx1 - wx0, a.real[0] + at, a.real[1] + at, a.real[2] + at);
      }
      // A channel whose window holds no light is not transformed: its
      // result is 0 (+0, whatever zeros it held).
      for (int c = 0; c < 3; ++c) {
        double* real = a.real[c];
        if (!any_light(real, size_t(t) * t)) {
          std::memset(real, 0, sizeof(double) * size_t(t) * t);
          continue;
        }
        fftw_execute_dft_r2c(e.forward, real, spectrum);
        multiply_spectrum(&spectrum[0][0], kernel.data() + size_t(c) * n, n);
        fftw_execute_dft_c2r(e.backward, spectrum, real);
      }
      for (int y = y0; y < oy1; ++y) {
        const size_t at = size_t(y - y0 + r) * t + size_t(r);
        merge_row(a.real[0] + at, a.real[1] + at, a.real[2] + at, scale, ox1 - x0, out.ptr<float>(y) + 3 * x0);
      }
    }
  });
}

}  // namespace eyestream::glare
