#include "glare/fft_convolver.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cstring>
#include <mutex>

namespace eyestream::glare {

namespace {

// FFTW's planner is not thread-safe; execution of distinct plans is.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

int fft_size(int minimum) {
  for (int n = std::max(minimum, 1);; ++n) {
    int m = n;
    for (int p : {2, 3, 5, 7})
      while (m % p == 0) m /= p;
    if (m == 1) return n;
  }
}

struct FftConvolver::Channel {
  double* real = nullptr;
  fftw_complex* spectrum = nullptr;
  fftw_plan forward = nullptr, backward = nullptr;
  Channel(int nx, int ny) {
    std::lock_guard<std::mutex> lock(planner_mutex());
    real = fftw_alloc_real(size_t(nx) * ny);
    spectrum = fftw_alloc_complex(size_t(nx / 2 + 1) * ny);
    forward = fftw_plan_dft_r2c_2d(ny, nx, real, spectrum, FFTW_ESTIMATE);
    backward = fftw_plan_dft_c2r_2d(ny, nx, spectrum, real, FFTW_ESTIMATE);
  }
  ~Channel() {
    std::lock_guard<std::mutex> lock(planner_mutex());
    fftw_destroy_plan(forward);
    fftw_destroy_plan(backward);
    fftw_free(real);
    fftw_free(spectrum);
  }
};

FftConvolver::FftConvolver(const ComponentKernels& k) : width_(k.core.cols / 2 + 1), height_(k.core.rows / 2 + 1) {
  // A W-wide frame and a kernel reaching +-(W - 1): any n >= 2W - 1 keeps
  // every offset distinct modulo n, so circular convolution is linear here.
  nx_ = fft_size(2 * width_ - 1);
  ny_ = fft_size(2 * height_ - 1);
  for (int c = 0; c < 3; ++c) channels_.push_back(std::make_unique<Channel>(nx_, ny_));
  const cv::Point centre = k.centre();
  auto spectrum_of = [&](const cv::Mat& kernel, std::vector<std::complex<double>>& out) {
    Channel& ch = *channels_[0];
    std::memset(ch.real, 0, sizeof(double) * size_t(nx_) * ny_);
    for (int y = 0; y < kernel.rows; ++y)
      for (int x = 0; x < kernel.cols; ++x) {
        const int wx = ((x - centre.x) % nx_ + nx_) % nx_, wy = ((y - centre.y) % ny_ + ny_) % ny_;
        ch.real[size_t(wy) * nx_ + wx] = kernel.at<double>(y, x);
      }
    fftw_execute(ch.forward);
    const size_t n = size_t(nx_ / 2 + 1) * ny_;
    out.resize(n);
    for (size_t i = 0; i < n; ++i) out[i] = {ch.spectrum[i][0], ch.spectrum[i][1]};
  };
  spectrum_of(k.core, core_);
  spectrum_of(k.inner, inner_);
  spectrum_of(k.outer, outer_);
  for (int c = 0; c < 3; ++c) spectrum_of(k.halo[c], halo_[c]);
}

FftConvolver::~FftConvolver() = default;

cv::Mat FftConvolver::convolve(const cv::Mat& rgb, const PsfWeights& w) const {
  CV_Assert(rgb.type() == CV_32FC3 && rgb.cols == width_ && rgb.rows == height_);
  cv::Mat out(rgb.size(), CV_32FC3);
  const double scale = 1.0 / (double(nx_) * ny_);
  cv::parallel_for_(cv::Range(0, 3), [&](const cv::Range& range) {
    for (int c = range.start; c < range.end; ++c) {
      Channel& ch = *channels_[size_t(c)];
      std::memset(ch.real, 0, sizeof(double) * size_t(nx_) * ny_);
      for (int y = 0; y < height_; ++y) {
        const cv::Vec3f* in = rgb.ptr<cv::Vec3f>(y);
        double* row = ch.real + size_t(y) * nx_;
        for (int x = 0; x < width_; ++x) row[x] = in[x][c];
      }
      fftw_execute(ch.forward);
      const size_t n = size_t(nx_ / 2 + 1) * ny_;
      for (size_t i = 0; i < n; ++i) {
        const std::complex<double> k =
            w.core * core_[i] + w.inner * inner_[i] + w.outer * outer_[i] + w.halo * halo_[c][i];
        const std::complex<double> v = std::complex<double>(ch.spectrum[i][0], ch.spectrum[i][1]) * k;
        ch.spectrum[i][0] = v.real();
        ch.spectrum[i][1] = v.imag();
      }
      fftw_execute(ch.backward);
      for (int y = 0; y < height_; ++y) {
        cv::Vec3f* o = out.ptr<cv::Vec3f>(y);
        const double* row = ch.real + size_t(y) * nx_;
        for (int x = 0; x < width_; ++x) o[x][c] = float(std::max(row[x] * scale, 0.0));
      }
    }
  });
  return out;
}

}  // namespace eyestream::glare
