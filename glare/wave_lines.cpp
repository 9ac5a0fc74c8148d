#include "glare/wave_lines.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "glare/linear_taps.hpp"

namespace eyestream::glare {

namespace {

// Lights are scattered one by one while that costs less than convolving
// their box by FFT: scattering costs lights x kernel pixels, the FFTs
// (three per channel) about the transform's pixels times this factor
// (measured on bench/glare_bench.cpp's WaveLines: at 1080p, 37 px/deg, a
// 133 px kernel and a whole-frame box of about 742 000 transform pixels,
// 2000 lights scattered took 12 ms more than 40, 6 us a light, and the
// FFTs 47 ms more: even at about 7 800 lights).
constexpr double kScatterPerTransformPixel = 180.0;

// The lines are drawn at most at this many px/deg: the pattern's own
// detail is 0.02 deg bins and 0.04 deg specks, so a finer frame gains
// nothing but cost (an FFT-sized filter per channel).
constexpr double kMostPixelsPerDegree = 35.0;

int reduction(double ppd) { return std::max(1, int(std::ceil(ppd / kMostPixelsPerDegree - 1e-9))); }

}  // namespace

WaveLines::WaveLines(const EyeOptics& optics, double frame_ppd)
    : factor_(reduction(frame_ppd)),
      ppd_(frame_ppd / factor_),
      haze_(optics.viewer().haze),
      radius_(std::max(1, int(kWavePatternReach_deg * ppd_))),
      smooth_(build_component_kernels(radius_ + 1, radius_ + 1, ppd_, optics)),
      aperture_(viewer_aperture(optics.viewer().seed, optics.viewer().eyelid_mrd1_mm)),
      hippus_(optics.viewer().seed) {}

WaveState WaveLines::state(double pupil_mm, double time_s, double light_x_deg, double light_y_deg) const {
  WaveState s;
  s.pupil_mm = std::clamp(pupil_mm + hippus_.offset_mm(pupil_mm, time_s), 1.5, Hippus::kMaxPupil_mm);
  s.time_s = time_s;
  s.light_x_deg = light_x_deg;
  s.light_y_deg = light_y_deg;
  return s;
}

cv::Mat line_part(const ComponentKernels& k, const PsfWeights& w, int c) {
  return k.inner * w.inner + k.outer * w.outer + k.halo[c] * w.halo;
}

cv::Mat with_wave_lines(const cv::Mat& lines, const WavePattern& p, int c, double haze) {
  // Per 1 px ring (of the kernel's pixels within the pattern), M scaled so
  // that the ring's light is unchanged: sum(lines M') = sum(lines).
  const int cx = lines.cols / 2, cy = lines.rows / 2;
  std::vector<double> plain(size_t(p.radius) + 2, 0.0), weighted(plain.size(), 0.0);
  const auto each = [&](auto&& f) {
    for (int y = std::max(-p.radius, -cy); y <= std::min(p.radius, lines.rows - 1 - cy); ++y)
      for (int x = std::max(-p.radius, -cx); x <= std::min(p.radius, lines.cols - 1 - cx); ++x) {
        const size_t ring = size_t(std::lround(std::hypot(x, y)));
        if (ring <= size_t(p.radius)) f(x, y, ring);
      }
  };
  each([&](int x, int y, size_t ring) {
    const double k = lines.at<double>(cy + y, cx + x);
    plain[ring] += k;
    weighted[ring] += k * p.rgb[c].at<double>(y + p.radius, x + p.radius);
  });
  cv::Mat out = lines.clone();
  each([&](int x, int y, size_t ring) {
    if (!(weighted[ring] > 0.0)) return;
    const double m = p.rgb[c].at<double>(y + p.radius, x + p.radius) * plain[ring] / weighted[ring];
    out.at<double>(cy + y, cx + x) *= 1.0 + (1.0 - haze) * (m - 1.0);
  });
  return out;
}

namespace {

// Adds delta, drawn on a frame reduced by `factor` whose rectangle `reach`
// it covers, to the frame pixels of `out` that read it, as linear
// resizing (pixel centres (j + 0.5) / factor - 0.5 of the reduced frame,
// clamped at its edges) would bring it back; negatives are set to 0 (the
// engines' rounding against the lines' exact sums). One pass, no
// full-frame temporary.
void add_upsampled(const std::array<cv::Mat, 3>& delta, const cv::Rect& reach, cv::Size reduced, int factor,
                   const cv::Rect& out, const cv::Mat& in, cv::Mat& result) {
  // Taps into the padded planes (outside the reach: their border of zeros).
  const auto taps = [&](int from, int count, int reach_from, int reach_size, int reduced_size) {
    std::vector<LinearTap> t = linear_taps(from, count, 1.0 / factor, reduced_size);
    for (LinearTap& tap : t) {
      tap.a = std::clamp(tap.a - reach_from + 1, 0, reach_size + 1);
      tap.b = std::clamp(tap.b - reach_from + 1, 0, reach_size + 1);
    }
    return t;
  };
  const std::vector<LinearTap> cols = taps(out.x, out.width, reach.x, reach.width, reduced.width);
  const std::vector<LinearTap> rows = taps(out.y, out.height, reach.y, reach.height, reduced.height);
  // The planes with a border of zeros (outside the reach the delta is 0).
  std::array<cv::Mat, 3> padded;
  for (int c = 0; c < 3; ++c) cv::copyMakeBorder(delta[size_t(c)], padded[size_t(c)], 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
  const size_t row_bytes = size_t(in.cols) * sizeof(cv::Vec3f);
  const bool copy = result.data != in.data;
  cv::parallel_for_(cv::Range(0, in.rows), [&](const cv::Range& range) {
    std::vector<cv::Vec3f> line(size_t(padded[0].cols));
    for (int y = range.start; y < range.end; ++y) {
      const float* from = in.ptr<float>(y);
      float* o = result.ptr<float>(y);
      if (y < out.y || y >= out.y + out.height) {
        if (copy) std::memcpy(o, from, row_bytes);
        continue;
      }
      if (copy) {
        std::memcpy(o, from, size_t(3 * out.x) * sizeof(float));
        const int right = out.x + out.width;
        std::memcpy(o + 3 * right, from + 3 * right, size_t(3 * (in.cols - right)) * sizeof(float));
      }
      const LinearTap& ty = rows[size_t(y - out.y)];
      // The row blended vertically, then each pixel horizontally.
      for (int c = 0; c < 3; ++c) {
        const float* a = padded[size_t(c)].ptr<float>(ty.a);
        const float* b = padded[size_t(c)].ptr<float>(ty.b);
        for (size_t k = 0; k < line.size(); ++k) line[k][c] = a[k] * (1.0f - ty.wb) + b[k] * ty.wb;
      }
      from += 3 * out.x, o += 3 * out.x;
      for (int j = 0; j < out.width; ++j, o += 3, from += 3) {
        const LinearTap& tx = cols[size_t(j)];
        const float *a = line[size_t(tx.a)].val, *b = line[size_t(tx.b)].val, wa = 1.0f - tx.wb;
        for (int c = 0; c < 3; ++c) o[c] = std::max(from[c] + a[c] * wa + b[c] * tx.wb, 0.0f);
      }
    }
  });
}

}  // namespace

bool WaveLines::add(const cv::Mat& frame, const PsfWeights& w, double pupil_mm, double time_s, cv::Point2d gaze,
                    const cv::Mat& retinal, cv::Mat& result) const {
  // On a frame reduced to at most kMostPixelsPerDegree (area means: the
  // same light), the lines brought back by linear interpolation.
  // A frame that is not whole blocks is padded with darkness first, so
  // that every reduced pixel is the mean of factor x factor frame pixels.
  cv::Mat rgb = frame;
  if (factor_ > 1) {
    const cv::Size reduced((frame.cols + factor_ - 1) / factor_, (frame.rows + factor_ - 1) / factor_);
    cv::Mat whole = frame;
    if (reduced.width * factor_ != frame.cols || reduced.height * factor_ != frame.rows)
      cv::copyMakeBorder(frame, whole, 0, reduced.height * factor_ - frame.rows, 0, reduced.width * factor_ - frame.cols,
                         cv::BORDER_CONSTANT, cv::Scalar::all(0));
    cv::resize(whole, rgb, reduced, 0, 0, cv::INTER_AREA);
  }
  const double sx = 1.0 / factor_, sy = 1.0 / factor_;
  Planes delta;
  cv::Rect reach;
  if (!lines(rgb, w, pupil_mm, time_s, {gaze.x * sx, gaze.y * sy}, delta, reach)) return false;
  // Every frame pixel whose interpolation reads the reach: linear
  // resizing samples at (j + 0.5) / s - 0.5 of the reduced frame.
  const auto first = [](int from, double s) { return int(std::floor((from - 0.5) / s - 0.5)); };
  const auto last = [](int to, double s) { return int(std::ceil((to + 0.5) / s - 0.5)); };
  const int fx = first(reach.x, sx), fy = first(reach.y, sy);
  const cv::Rect out = cv::Rect(fx, fy, last(reach.x + reach.width, sx) - fx + 1, last(reach.y + reach.height, sy) - fy + 1) &
                       cv::Rect(0, 0, frame.cols, frame.rows);
  if (result.data != retinal.data) result.create(retinal.size(), CV_32FC3);
  add_upsampled(delta, reach, rgb.size(), factor_, out, retinal, result);
  return true;
}

bool WaveLines::lines(const cv::Mat& rgb, const PsfWeights& w, double pupil_mm, double time_s, cv::Point2d gaze,
                      Planes& delta, cv::Rect& reach) const {
  // The lights: luminance at least kContrast times their surround's, the
  // mean over the frame's pixels between the inner and the outer square
  // (box sums read from one integral image; the counts are separable).
  cv::Mat luminance, integral;
  cv::transform(rgb, luminance, cv::Matx13f(0.2126f, 0.7152f, 0.0722f));
  cv::integral(luminance, integral, CV_64F);
  const int half_in = std::max(1, int(std::lround(kSurroundInner_deg * ppd_)) | 1) / 2;
  const int half_out = std::max(2 * half_in + 3, int(std::lround(kSurroundOuter_deg * ppd_)) | 1) / 2;
  std::vector<std::vector<Light>> found(size_t(rgb.rows));
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& range) {
    for (int y = range.start; y < range.end; ++y) {
      const float* l = luminance.ptr<float>(y);
      const cv::Vec3f* in = rgb.ptr<cv::Vec3f>(y);
      const int iy0 = std::max(0, y - half_in), iy1 = std::min(rgb.rows, y + half_in + 1);
      const int oy0 = std::max(0, y - half_out), oy1 = std::min(rgb.rows, y + half_out + 1);
      const double *ia = integral.ptr<double>(iy0), *ib = integral.ptr<double>(iy1);
      const double *oa = integral.ptr<double>(oy0), *ob = integral.ptr<double>(oy1);
      for (int x = 0; x < rgb.cols; ++x) {
        if (!(l[x] > 0.0f)) continue;
        const int ix0 = std::max(0, x - half_in), ix1 = std::min(rgb.cols, x + half_in + 1);
        const int ox0 = std::max(0, x - half_out), ox1 = std::min(rgb.cols, x + half_out + 1);
        const double inner = ib[ix1] - ib[ix0] - ia[ix1] + ia[ix0];
        const double outer = ob[ox1] - ob[ox0] - oa[ox1] + oa[ox0];
        const double count = double(ox1 - ox0) * (oy1 - oy0) - double(ix1 - ix0) * (iy1 - iy0);
        if (l[x] >= kContrast * (outer - inner) / std::max(count, 1.0)) found[size_t(y)].push_back({x, y, in[x], l[x]});
      }
    }
  });
  std::vector<Light> lights;
  for (const std::vector<Light>& row : found) lights.insert(lights.end(), row.begin(), row.end());
  if (lights.empty()) return false;
  const Light& brightest = *std::max_element(lights.begin(), lights.end(), [](const Light& a, const Light& b) {
    return a.luminance < b.luminance;
  });
  const WavePattern pattern = wave_pattern(
      aperture_, state(pupil_mm, time_s, (brightest.x + 0.5 - gaze.x) / ppd_, (brightest.y + 0.5 - gaze.y) / ppd_),
      ppd_, radius_);
  // The addition per channel: the line part times (1 - haze)(M - 1).
  const int r = radius_, n = 2 * r + 1;
  cv::Mat added[3];
  for (int c = 0; c < 3; ++c) {
    const cv::Mat lines = line_part(smooth_, w, c);
    const cv::Mat change = with_wave_lines(lines, pattern, c, haze_) - lines;
    change.convertTo(added[c], CV_32F);
  }
  int x0 = rgb.cols, y0 = rgb.rows, x1 = -1, y1 = -1;
  for (const Light& l : lights) x0 = std::min(x0, l.x), y0 = std::min(y0, l.y), x1 = std::max(x1, l.x), y1 = std::max(y1, l.y);
  reach = cv::Rect(x0 - r, y0 - r, x1 - x0 + n, y1 - y0 + n) & cv::Rect(0, 0, rgb.cols, rgb.rows);
  for (cv::Mat& d : delta) d = cv::Mat::zeros(reach.size(), CV_32F);  // the reach's pixels
  const cv::Size box(x1 - x0 + 1, y1 - y0 + 1), full(box.width + n - 1, box.height + n - 1);
  const cv::Size size(cv::getOptimalDFTSize(full.width), cv::getOptimalDFTSize(full.height));
  const bool scatter = spread_ == Spread::automatic
                           ? double(lights.size()) * n * n <= kScatterPerTransformPixel * size.area()
                           : spread_ == Spread::scatter;
  if (scatter) {
    // Row by row, channel by channel, each light in order (the lights are
    // in row order): the same sums on any thread count.
    cv::parallel_for_(cv::Range(reach.y, reach.y + reach.height), [&](const cv::Range& rows) {
      for (int y = rows.start; y < rows.end; ++y) {
        const auto from_light = std::lower_bound(lights.begin(), lights.end(), y - r,
                                                 [](const Light& l, int row) { return l.y < row; });
        const auto to_light = std::upper_bound(from_light, lights.end(), y + r,
                                               [](int row, const Light& l) { return row < l.y; });
        for (int c = 0; c < 3; ++c) {
          float* row = delta[size_t(c)].ptr<float>(y - reach.y);
          for (auto l = from_light; l != to_light; ++l) {
            const int from = std::max(0, l->x - r), to = std::min(rgb.cols - 1, l->x + r);
            float* out = row + (from - reach.x);
            const float* k = added[c].ptr<float>(y - l->y + r) + (from - l->x + r);
            const float v = l->rgb[c];
            for (int i = 0; i <= to - from; ++i) out[i] += v * k[i];
          }
        }
      }
    });
  } else {
    // By FFT, one channel per task: the lights' box convolved in full
    // (box + n - 1 each way), the part inside the frame kept.
    // The full convolution's (0, 0) is the box's corner moved r up and left.
    const cv::Rect placed(x0 - r, y0 - r, full.width, full.height);
    cv::parallel_for_(cv::Range(0, 3), [&](const cv::Range& channels) {
      for (int c = channels.start; c < channels.end; ++c) {
        cv::Mat lit = cv::Mat::zeros(size, CV_32F), kernel = cv::Mat::zeros(size, CV_32F);
        for (const Light& l : lights) lit.at<float>(l.y - y0, l.x - x0) = l.rgb[c];
        added[c].copyTo(kernel(cv::Rect(0, 0, n, n)));
        cv::dft(lit, lit, 0, box.height);
        cv::dft(kernel, kernel, 0, n);
        cv::mulSpectrums(lit, kernel, lit, 0);
        cv::dft(lit, lit, cv::DFT_INVERSE | cv::DFT_SCALE, full.height);
        lit(cv::Rect(reach.x - placed.x, reach.y - placed.y, reach.width, reach.height)).copyTo(delta[size_t(c)]);
      }
    });
  }
  return true;
}

}  // namespace eyestream::glare
