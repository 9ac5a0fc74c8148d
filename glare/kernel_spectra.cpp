#include "glare/kernel_spectra.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>

#include "glare/fftw_planner.hpp"
#include "glare/huge_pages.hpp"

namespace eyestream::glare {

void kernel_spectra(const std::vector<const cv::Mat*>& kernels, int nx, int ny,
                    const std::function<void(int, const double (*)[2])>& keep) {
  const size_t n_real = size_t(nx) * ny, n = size_t(nx / 2 + 1) * ny;
  fftw_plan plan;
  {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    double* real = fftw_alloc_real(n_real);
    fftw_complex* spectrum = fftw_alloc_complex(n);
    plan = fftw_plan_dft_r2c_2d(ny, nx, real, spectrum, FFTW_ESTIMATE);
    fftw_free(real);
    fftw_free(spectrum);
  }
  std::vector<char> refused(kernels.size(), 0);
  cv::parallel_for_(cv::Range(0, int(kernels.size())), [&](const cv::Range& r) {
    double* real = fftw_alloc_real(n_real);
    fftw_complex* spectrum = fftw_alloc_complex(n);
    prefer_huge_pages(real, sizeof(double) * n_real);
    prefer_huge_pages(spectrum, sizeof(fftw_complex) * n);
    for (int k = r.start; k < r.end; ++k) {
      const cv::Mat& kernel = *kernels[size_t(k)];
      std::memset(real, 0, sizeof(double) * n_real);
      const int cx = kernel.cols / 2, cy = kernel.rows / 2;
      for (int y = 0; y < kernel.rows; ++y)
        for (int x = 0; x < kernel.cols; ++x) {
          const int wx = ((x - cx) % nx + nx) % nx, wy = ((y - cy) % ny + ny) % ny;
          real[size_t(wy) * nx + wx] += kernel.at<double>(y, x);
        }
      fftw_execute_dft_r2c(plan, real, spectrum);
      double largest = 0.0, imaginary = 0.0;
      for (size_t i = 0; i < n; ++i) {
        largest = std::max(largest, std::abs(spectrum[i][0]));
        imaginary = std::max(imaginary, std::abs(spectrum[i][1]));
      }
      refused[size_t(k)] = !(imaginary <= 1e-9 * largest);
      keep(k, spectrum);
    }
    fftw_free(real);
    fftw_free(spectrum);
  });
  {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(plan);
  }
  for (char bad : refused) CV_Assert(!bad && "glare kernels must be point-symmetric (a real spectrum)");
}

}  // namespace eyestream::glare
