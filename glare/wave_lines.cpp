#include "glare/wave_lines.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace eyestream::glare {

namespace {

constexpr size_t kScatterAtMost = 400;

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
      aperture_(viewer_aperture(optics.viewer().seed)),
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

bool WaveLines::add(const cv::Mat& frame, const PsfWeights& w, double pupil_mm, double time_s, cv::Point2d gaze,
                    cv::Mat& retinal) const {
  // On a frame reduced to at most kMostPixelsPerDegree (area means: the
  // same light), the lines brought back by linear interpolation.
  cv::Mat rgb = frame;
  if (factor_ > 1)
    cv::resize(frame, rgb, cv::Size((frame.cols + factor_ - 1) / factor_, (frame.rows + factor_ - 1) / factor_), 0, 0,
               cv::INTER_AREA);
  const double sx = double(rgb.cols) / frame.cols, sy = double(rgb.rows) / frame.rows;
  cv::Mat delta = cv::Mat::zeros(rgb.size(), CV_32FC3);
  cv::Rect reach;
  if (!lines(rgb, w, pupil_mm, time_s, {gaze.x * sx, gaze.y * sy}, delta, reach)) return false;
  cv::Rect out(0, 0, frame.cols, frame.rows);
  if (factor_ > 1) {
    cv::resize(delta, delta, frame.size(), 0, 0, cv::INTER_LINEAR);
    // Every frame pixel whose interpolation reads the reach: linear
    // resizing samples at (j + 0.5) / s - 0.5 of the reduced frame.
    const auto first = [](int from, double s) { return int(std::floor((from - 0.5) / s - 0.5)); };
    const auto last = [](int to, double s) { return int(std::ceil((to + 0.5) / s - 0.5)); };
    const int fx = first(reach.x, sx), fy = first(reach.y, sy);
    out &= cv::Rect(fx, fy, last(reach.x + reach.width, sx) - fx + 1, last(reach.y + reach.height, sy) - fy + 1);
  } else {
    out = reach;
  }
  cv::Mat touched = retinal(out);
  touched += delta(out);
  cv::max(touched, 0.0f, touched);  // the engines' rounding against the lines' exact sums
  return true;
}

bool WaveLines::lines(const cv::Mat& rgb, const PsfWeights& w, double pupil_mm, double time_s, cv::Point2d gaze,
                      cv::Mat& delta, cv::Rect& reach) const {
  // The lights: luminance at least kContrast times their surround's, the
  // mean over the frame's pixels between the inner and the outer square.
  cv::Mat luminance, inner, outer, count_in, count_out;
  cv::transform(rgb, luminance, cv::Matx13f(0.2126f, 0.7152f, 0.0722f));
  const int box_in = std::max(1, int(std::lround(kSurroundInner_deg * ppd_)) | 1);
  const int box_out = std::max(box_in + 2, int(std::lround(kSurroundOuter_deg * ppd_)) | 1);
  const cv::Mat ones(luminance.size(), CV_32F, cv::Scalar(1.0f));
  const auto sum = [](const cv::Mat& m, int box, cv::Mat& out) {
    cv::boxFilter(m, out, CV_64F, cv::Size(box, box), cv::Point(-1, -1), false, cv::BORDER_CONSTANT);
  };
  sum(luminance, box_in, inner), sum(luminance, box_out, outer), sum(ones, box_in, count_in), sum(ones, box_out, count_out);
  const cv::Mat surround = (outer - inner) / cv::max(count_out - count_in, 1.0);
  std::vector<Light> lights;
  for (int y = 0; y < rgb.rows; ++y) {
    const float* l = luminance.ptr<float>(y);
    const double* s = surround.ptr<double>(y);
    const cv::Vec3f* in = rgb.ptr<cv::Vec3f>(y);
    for (int x = 0; x < rgb.cols; ++x)
      if (l[x] > 0.0f && l[x] >= kContrast * s[x]) lights.push_back({x, y, in[x], l[x]});
  }
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
  if (lights.size() <= kScatterAtMost) {
    // Row by row, each light in order: the same sums on any thread count.
    cv::parallel_for_(cv::Range(reach.y, reach.y + reach.height), [&](const cv::Range& rows) {
      for (int y = rows.start; y < rows.end; ++y) {
        cv::Vec3f* out = delta.ptr<cv::Vec3f>(y);
        for (const Light& l : lights) {
          const int ky = y - l.y + r;
          if (ky < 0 || ky >= n) continue;
          const int from = std::max(0, l.x - r), to = std::min(rgb.cols - 1, l.x + r);
          const float* k[3] = {added[0].ptr<float>(ky), added[1].ptr<float>(ky), added[2].ptr<float>(ky)};
          for (int x = from; x <= to; ++x)
            for (int c = 0; c < 3; ++c) out[x][c] += l.rgb[c] * k[c][x - l.x + r];
        }
      }
    });
  } else {
    // By FFT, one channel per task: the lights' box convolved in full
    // (box + n - 1 each way), the part inside the frame kept.
    const cv::Size box(x1 - x0 + 1, y1 - y0 + 1), full(box.width + n - 1, box.height + n - 1);
    const cv::Size size(cv::getOptimalDFTSize(full.width), cv::getOptimalDFTSize(full.height));
    cv::Mat spread[3];
    cv::parallel_for_(cv::Range(0, 3), [&](const cv::Range& channels) {
      for (int c = channels.start; c < channels.end; ++c) {
        cv::Mat lit = cv::Mat::zeros(size, CV_32F), kernel = cv::Mat::zeros(size, CV_32F);
        for (const Light& l : lights) lit.at<float>(l.y - y0, l.x - x0) = l.rgb[c];
        added[c].copyTo(kernel(cv::Rect(0, 0, n, n)));
        cv::dft(lit, lit, 0, box.height);
        cv::dft(kernel, kernel, 0, n);
        cv::mulSpectrums(lit, kernel, lit, 0);
        cv::dft(lit, lit, cv::DFT_INVERSE | cv::DFT_SCALE, full.height);
        spread[c] = lit(cv::Rect(0, 0, full.width, full.height));
      }
    });
    cv::Mat sum;
    cv::merge(spread, 3, sum);
    // The full convolution's (0, 0) is the box's corner moved r up and left.
    const cv::Rect placed(x0 - r, y0 - r, full.width, full.height);
    delta(reach) += sum(cv::Rect(reach.x - placed.x, reach.y - placed.y, reach.width, reach.height));
  }
  return true;
}

}  // namespace eyestream::glare
