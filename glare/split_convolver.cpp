#include "glare/split_convolver.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace eyestream::glare {

namespace {

// The near window w(r) for r in full-resolution pixels.
double near_window(double r, double radius) {
  const double inner = radius / 2.0;
  if (r <= inner) return 1.0;
  if (r >= radius) return 0.0;
  return (radius - r) / (radius - inner);
}

// Every component kernel of `k`, for loops over them.
std::vector<cv::Mat*> components(ComponentKernels& k) {
  return {&k.core, &k.inner, &k.outer, &k.halo[0], &k.halo[1], &k.halo[2]};
}

// Multiplies `kernel` (centred) by window(r * pixel_scale), or by
// 1 - window when `complement`.
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

struct Source {
  int x, y;
  cv::Vec3f value;
};

}  // namespace

SplitConvolver::SplitConvolver(int width, int height, double ppd, int factor, const EyeOptics& optics)
    : width_(width), height_(height), factor_(std::max(factor, 2)), radius_(8 * factor_) {
  low_width_ = (width + factor_ - 1) / factor_;
  low_height_ = (height + factor_ - 1) / factor_;
  near_ = build_component_kernels(radius_ + 1, radius_ + 1, ppd, optics);
  ComponentKernels far = build_component_kernels(low_width_, low_height_, ppd / factor_, optics);
  std::vector<cv::Mat*> n = components(near_), f = components(far);
  for (size_t i = 0; i < n.size(); ++i) {
    apply_window(*n[i], 1.0, radius_, false);
    apply_window(*f[i], factor_, radius_, true);
  }
  far_ = std::make_unique<FftConvolver>(far);
  near_fft_ = std::make_unique<FftConvolver>(near_, width, height);
}

SplitConvolver::~SplitConvolver() = default;

cv::Mat SplitConvolver::convolve(const cv::Mat& rgb, const PsfWeights& w) const {
  CV_Assert(rgb.cols == width_ && rgb.rows == height_ && rgb.type() == CV_32FC3);
  cv::Mat out = spread_near(rgb, w) + spread_far(rgb, w);
  cv::max(out, 0.0, out);
  return out;
}

cv::Mat SplitConvolver::spread_near(const cv::Mat& rgb, const PsfWeights& w) const {
  // Dense (the whole image, or many lights): by FFT, padded by R only;
  // decided as soon as the sources' direct cost exceeds the FFT's.
  const int r = radius_, side = 2 * r + 1;
  const size_t most = size_t(0.5 * double(near_fft_->transform_size().area()) / (double(side) * side));
  std::vector<Source> sources;  // row by row: sorted by y
  cv::Mat out;
  for (int y = 0; y < rgb.rows; ++y) {
    const cv::Vec3f* row = rgb.ptr<cv::Vec3f>(y);
    for (int x = 0; x < rgb.cols; ++x)
      if (row[x] != cv::Vec3f()) sources.push_back({x, y, row[x]});
    if (sources.size() > most) {
      near_fft_->convolve(rgb, w, out);
      return out;
    }
  }
  out = cv::Mat::zeros(rgb.size(), CV_32FC3);
  cv::Mat kernel[3];
  for (int c = 0; c < 3; ++c) combined_kernel(near_, w, c).convertTo(kernel[c], CV_32F);
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

cv::Mat SplitConvolver::spread_far(const cv::Mat& rgb, const PsfWeights& w) const {
  // Block sums of the input on the reduced frame (zero-padded to whole blocks).
  cv::Mat padded;
  cv::copyMakeBorder(rgb, padded, 0, low_height_ * factor_ - height_, 0, low_width_ * factor_ - width_,
                     cv::BORDER_CONSTANT, cv::Scalar::all(0));
  cv::Mat low;
  cv::resize(padded, low, cv::Size(low_width_, low_height_), 0, 0, cv::INTER_AREA);
  low *= double(factor_) * factor_;
  const cv::Mat spread = far_->convolve(low, w);  // energy landing on each block
  // Back to full resolution as a density, keeping each channel's energy.
  cv::Mat up;
  cv::resize(spread * (1.0 / (double(factor_) * factor_)), up, padded.size(), 0, 0, cv::INTER_LINEAR);
  const cv::Scalar want = cv::sum(spread), got = cv::sum(up);
  cv::Scalar scale;
  for (int c = 0; c < 3; ++c) scale[c] = got[c] > 0 ? want[c] / got[c] : 0.0;
  cv::multiply(up, scale, up);
  return up(cv::Rect(0, 0, width_, height_)).clone();
}

}  // namespace eyestream::glare
