#include "glare/fft_convolver.hpp"

#include "glare/channel_rows.hpp"
#include "glare/fftw_planner.hpp"
#include "glare/huge_pages.hpp"
#include "glare/kernel_spectra.hpp"
#include "glare/vector_clones.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace eyestream::glare {

namespace {

// FFTW's interface, under names the engine reads well with.
struct Fftw {
  using Plan = fftw_plan;
  using Complex = fftw_complex;
  static double* real(size_t n) { return fftw_alloc_real(n); }
  static Complex* complex(size_t n) { return fftw_alloc_complex(n); }
  static void free(void* p) { fftw_free(p); }
  static Plan r2c(int n, double* in, Complex* out) {
    return make_fftw_plan([&](unsigned flags) { return fftw_plan_dft_r2c_1d(n, in, out, flags); });
  }
  static Plan c2r(int n, Complex* in, double* out) {
    return make_fftw_plan([&](unsigned flags) { return fftw_plan_dft_c2r_1d(n, in, out, flags); });
  }
  // `howmany` contiguous transforms of n points, one after the other.
  static Plan columns(int n, int howmany, Complex* data, int sign) {
    return make_fftw_plan([&](unsigned flags) {
      return fftw_plan_many_dft(1, &n, howmany, data, nullptr, 1, n, data, nullptr, 1, n, sign, flags);
    });
  }
  static void r2c(Plan p, double* in, Complex* out) { fftw_execute_dft_r2c(p, in, out); }
  static void c2r(Plan p, Complex* in, double* out) { fftw_execute_dft_c2r(p, in, out); }
  static void c2c(Plan p, Complex* data) { fftw_execute_dft(p, data, data); }
  static void destroy(Plan p) { fftw_destroy_plan(p); }
};


constexpr int kColumnBlock = 16;  // columns transformed together (fixed: results do not depend on threads)

// The most memory the three channels' spectra may take to be held at once.
// At 1080p `fast`'s near plane (14 MB) is held so, and its glare took 13.7
// ms a frame in the glare bench against 14.55 one channel at a time
// (medians of four, alternating); `balanced`'s middle level (then 27 MB,
// 22 MB since its transforms are 1200 x 768) took 51.1 against 51.45 and
// 11-19 MiB more in the bench, so it stays one channel at a time. At 720p that level (12 MB) is held at once: 34.2
// against 33.9 ms, the same within the machine's noise.
constexpr size_t kChannelsTogetherBytes = size_t(16) << 20;

// The per-value loops, compiled for AVX-512 and AVX2 beside the baseline
// (glare/vector_clones.hpp: no FMA, so every version gives the same bytes).

// A block's n columns (complex, row y's at block[y kColumnBlock + j]) into
// `columns`, one after the other (column j's value y at j ny + y), or back.
EYESTREAM_VECTOR_CLONES
void block_to_columns(const double* block, int n, int ny, double* columns) {
  for (int y = 0; y < ny; ++y) {  // the block read in order; each column written one value on
    const double* v = block + 2 * size_t(y) * kColumnBlock;
    for (int j = 0; j < n; ++j) {
      columns[2 * (size_t(j) * ny + y)] = v[2 * j];
      columns[2 * (size_t(j) * ny + y) + 1] = v[2 * j + 1];
    }
  }
}

EYESTREAM_VECTOR_CLONES
void columns_to_block(const double* columns, int n, int ny, double* block) {
  for (int y = 0; y < ny; ++y) {
    double* v = block + 2 * size_t(y) * kColumnBlock;
    for (int j = 0; j < n; ++j) {
      v[2 * j] = columns[2 * (size_t(j) * ny + y)];
      v[2 * j + 1] = columns[2 * (size_t(j) * ny + y) + 1];
    }
  }
}

// m complex values times the real w0 k0 + w1 k1 + w2 k2 + w3 k3.
EYESTREAM_VECTOR_CLONES
void multiply_by_combined(double* values, const double* const k[4], const double w[4], size_t m) {
  for (size_t i = 0; i < m; ++i) {
    const double kr = w[0] * k[0][i] + w[1] * k[1][i] + w[2] * k[2][i] + w[3] * k[3][i];
    values[2 * i] *= kr;
    values[2 * i + 1] *= kr;
  }
}

}  // namespace

int fft_size(int minimum) {
  // From 64 up, a multiple of 16 as well: FFTW's estimated plans run such
  // sizes at about two thirds of the time per point of sizes with more
  // factors of 5 or 7 (docs/performance.md: 1250 x 840 became 1280 x 864
  // for `balanced`'s middle level at 1080p, 2026-12-05; 1156 x 756 becomes
  // 1200 x 768 since the fourteenth session's narrower tail ramp).
  const int unit = minimum >= 64 ? 16 : 1;
  for (int n = std::max(minimum, 1);; ++n) {
    if (n % unit != 0) continue;
    int m = n;
    for (int p : {2, 3, 5, 7})
      while (m % p == 0) m /= p;
    if (m == 1) return n;
  }
}

struct FftConvolver::Engine {
  virtual ~Engine() = default;
  virtual void convolve(const cv::Mat& rgb, const ChannelWeights& w, cv::Mat& out) const = 0;
  int nx = 0, ny = 0;
  int channels_at_once = 1;
};

namespace {

// A 2-D transform done as row transforms (r2c, only the frame's rows) and
// column transforms (c2c, in blocks of kColumnBlock), rows shared out
// among threads and blocks in fixed stripes, one per thread: every row and
// column is computed by the same plan whatever thread runs it. Each
// spectrum is held block-major: a block's ny x kColumnBlock values are
// contiguous, and each block is copied, a column after the other, into
// its stripe's array for the column transforms (in rows of the whole
// spectrum, the same column's values would be a row's length apart, and
// the large power-of-two strides thrash the cache).
class RowColumnEngine final : public FftConvolver::Engine {
  using F = Fftw;
  using T = double;

 public:
  RowColumnEngine(const ComponentKernels& k, int width, int height) : width_(width), height_(height) {
    const int reach_x = k.core.cols / 2, reach_y = k.core.rows / 2;
    // Any n >= W + reach keeps every offset of a light inside the frame
    // from wrapping onto the frame.
    nx = fft_size(width + reach_x);
    ny = fft_size(height + reach_y);
    nc_ = nx / 2 + 1;
    stride_ = (nc_ + kColumnBlock - 1) / kColumnBlock * kColumnBlock;  // whole blocks: every block aligned alike
    // Kernel spectra (real) block by block, each block's kColumnBlock
    // columns of ny values one after the other, as the column pass holds
    // the block's spectrum.
    // Each value is written once, as its kernel's transform is kept (the
    // padding columns of the last block as 0): not filled first, which
    // cost a pass over them all (22 MB in `balanced` at 1080p).
    for (std::unique_ptr<T[]>& s : spectra_) {
      s.reset(new T[size_t(ny) * stride_]);
      prefer_huge_pages(s.get(), sizeof(T) * size_t(ny) * stride_);
    }
    kernel_spectra({&k.core, &k.inner, &k.outer, &k.halo[0], &k.halo[1], &k.halo[2]}, nx, ny,
                   [&](int i, const fftw_complex* s) {
                     T* out = spectra_[i].get();
                     for (int y = 0; y < ny; ++y)
                       for (int x = 0; x < stride_; ++x)
                         out[(size_t(x / kColumnBlock) * kColumnBlock + x % kColumnBlock) * ny + y] =
                             x < nc_ ? T(s[size_t(y) * nc_ + x][0]) : T(0);
                   });
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    // Every channel's spectrum at once where the three take at most
    // kChannelsTogetherBytes, else one.
    channels_at_once = 3 * sizeof(F::Complex) * size_t(ny) * stride_ <= kChannelsTogetherBytes ? 3 : 1;
    data_ = F::complex(size_t(channels_at_once) * ny * stride_);
    prefer_huge_pages(data_, sizeof(F::Complex) * size_t(channels_at_once) * ny * stride_);
    T* row = F::real(size_t(nx));
    F::Complex* spectrum_row = F::complex(size_t(nc_));
    forward_row_ = F::r2c(nx, row, spectrum_row);
    backward_row_ = F::c2r(nx, spectrum_row, row);
    F::free(row);
    F::free(spectrum_row);
    const int last = nc_ % kColumnBlock;
    F::Complex* columns = F::complex(size_t(ny) * kColumnBlock);
    for (int sign : {FFTW_FORWARD, FFTW_BACKWARD}) {
      column_[sign == FFTW_FORWARD ? 0 : 1][0] = F::columns(ny, kColumnBlock, columns, sign);
      column_[sign == FFTW_FORWARD ? 0 : 1][1] = last ? F::columns(ny, last, columns, sign) : nullptr;
    }
    F::free(columns);
  }

  ~RowColumnEngine() override {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    F::destroy(forward_row_);
    F::destroy(backward_row_);
    for (auto& pair : column_)
      for (auto& p : pair)
        if (p) F::destroy(p);
    F::free(data_);
    for (F::Complex* c : columns_) F::free(c);
  }

  void convolve(const cv::Mat& rgb, const ChannelWeights& w, cv::Mat& out) const override {
    CV_Assert(rgb.type() == CV_32FC3 && rgb.cols == width_ && rgb.rows == height_);
    out.create(rgb.size(), CV_32FC3);
    if (channels_at_once == 3)
      convolve_channels(rgb, w, 0, out);
    else  // one channel after the other through one spectrum's memory
      for (int c = 0; c < 3; ++c) convolve_channels(rgb, w, c, out);
  }

 private:
  // Channels [first, first + channels_at_once) of `rgb` convolved into `out`:
  // every channel a row pass reads or writes in one sweep of the frame's
  // row, and in the column pass each block's channels one after the other
  // while its kernel values are in the cache.
  void convolve_channels(const cv::Mat& rgb, const ChannelWeights& w, int first, cv::Mat& out) const {
    const int held = channels_at_once;
    // Rows: r2c of the frame's rows; the padding rows are 0.
    cv::parallel_for_(cv::Range(0, ny), [&](const cv::Range& r) {
      T* rows[3] = {};
      for (int i = 0; i < held; ++i) rows[i] = F::real(size_t(nx));
      F::Complex* spectrum = F::complex(size_t(stride_));
      for (int y = r.start; y < r.end; ++y) {
        const bool padding = y >= height_;  // 0 in every channel's spectrum: zeroed once
        if (padding)
          std::memset(static_cast<void*>(spectrum), 0, sizeof(F::Complex) * size_t(stride_));
        else if (held == 3)
          split_row(rgb.ptr<float>(y), width_, rows[0], rows[1], rows[2]);
        else
          channel_to_row(rgb.ptr<float>(y), first, width_, rows[0]);
        for (int i = 0; i < held; ++i) {
          if (!padding) {
            std::fill(rows[i] + width_, rows[i] + nx, T(0));
            F::r2c(forward_row_, rows[i], spectrum);
            std::memset(static_cast<void*>(spectrum + nc_), 0, sizeof(F::Complex) * size_t(stride_ - nc_));
          }
          for (int b = 0; b < stride_ / kColumnBlock; ++b)
            std::memcpy(static_cast<void*>(at(i, b, y)), spectrum + b * kColumnBlock,
                        sizeof(F::Complex) * kColumnBlock);
        }
      }
      for (int i = 0; i < held; ++i) F::free(rows[i]);
      F::free(spectrum);
    });
    // Columns: forward, times the channel's kernel, back; block by block,
    // each block's columns copied one after the other into its share's
    // array first and back after (FFTW's own buffered plans for strided
    // columns allocate their buffers at every execution).
    const int blocks = (nc_ + kColumnBlock - 1) / kColumnBlock;
    const int shares = std::min(blocks, std::max(1, cv::getNumThreads()));
    while (int(columns_.size()) < shares) columns_.push_back(F::complex(size_t(ny) * kColumnBlock));
    cv::parallel_for_(cv::Range(0, shares), [&](const cv::Range& r) {
      for (int k = r.start; k < r.end; ++k)
      for (int b = k; b < blocks; b += shares) {
        const int x0 = b * kColumnBlock;
        const int n = std::min(kColumnBlock, nc_ - x0), partial = n < kColumnBlock;
        const size_t start = size_t(b) * ny * kColumnBlock;
        for (int i = 0; i < held; ++i) {
          const int c = first + i;
          const PsfWeights& wc = w[size_t(c)];
          const T weight[4] = {T(wc.core), T(wc.inner), T(wc.outer), T(wc.halo)};
          F::Complex* block = at(i, b, 0);
          T* column = reinterpret_cast<T*>(columns_[size_t(k)]);  // column j's value y at 2 (j ny + y)
          block_to_columns(reinterpret_cast<const T*>(block), n, ny, column);
          F::c2c(column_[0][partial], columns_[size_t(k)]);
          const T* kernel[4] = {spectra_[0].get() + start, spectra_[1].get() + start, spectra_[2].get() + start,
                                spectra_[3 + c].get() + start};
          multiply_by_combined(column, kernel, weight, size_t(n) * size_t(ny));
          F::c2c(column_[1][partial], columns_[size_t(k)]);
          columns_to_block(column, n, ny, reinterpret_cast<T*>(block));
        }
      }
    });
    // Rows back, the frame's rows only.
    const T scale = T(1.0 / (double(nx) * ny));
    cv::parallel_for_(cv::Range(0, height_), [&](const cv::Range& r) {
      T* rows[3] = {};
      for (int i = 0; i < held; ++i) rows[i] = F::real(size_t(nx));
      F::Complex* spectrum = F::complex(size_t(stride_));
      for (int y = r.start; y < r.end; ++y) {
        for (int i = 0; i < held; ++i) {
          for (int b = 0; b < stride_ / kColumnBlock; ++b)
            std::memcpy(static_cast<void*>(spectrum + b * kColumnBlock), at(i, b, y),
                        sizeof(F::Complex) * kColumnBlock);
          F::c2r(backward_row_, spectrum, rows[i]);
        }
        if (held == 3)
          merge_row(rows[0], rows[1], rows[2], scale, width_, out.ptr<float>(y));
        else
          row_to_channel(rows[0], scale, first, width_, out.ptr<float>(y));
      }
      for (int i = 0; i < held; ++i) F::free(rows[i]);
      F::free(spectrum);
    });
  }
  // Row y's kColumnBlock values of block b of held spectrum i.
  F::Complex* at(int i, int b, int y) const {
    return data_ + size_t(i) * size_t(ny) * size_t(stride_) + (size_t(b) * size_t(ny) + size_t(y)) * kColumnBlock;
  }

  int width_, height_, nc_ = 0, stride_ = 0;
  std::unique_ptr<T[]> spectra_[6];  // core, inner, outer, halo R, G, B; real, block-major, column after column in a block
  F::Complex* data_ = nullptr;  // the spectra of the channels being convolved
  F::Plan forward_row_ = nullptr, backward_row_ = nullptr;
  F::Plan column_[2][2] = {};  // [forward, backward][whole block, last partial block]
  mutable std::vector<F::Complex*> columns_;  // one block's columns, one after the other, per share of the blocks
};

}  // namespace

FftConvolver::FftConvolver(const ComponentKernels& k)
    : FftConvolver(k, k.core.cols / 2 + 1, k.core.rows / 2 + 1) {}

FftConvolver::FftConvolver(const ComponentKernels& k, int width, int height)
    : engine_(std::make_unique<RowColumnEngine>(k, width, height)) {}

FftConvolver::~FftConvolver() = default;

void FftConvolver::convolve(const cv::Mat& rgb, const ChannelWeights& w, cv::Mat& out) const {
  engine_->convolve(rgb, w, out);
}

cv::Size FftConvolver::transform_size() const { return {engine_->nx, engine_->ny}; }

int FftConvolver::channels_at_once() const { return engine_->channels_at_once; }

}  // namespace eyestream::glare
