#include "glare/flare_lines.hpp"

#include <algorithm>
#include <cmath>

namespace eyestream::glare {

namespace {

constexpr double kTwoPi = 2.0 * M_PI;

// SplitMix64 (Steele, Lea, Flood 2014): the same numbers on every platform.
struct SplitMix {
  std::uint64_t state;
  double uniform() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return double(z >> 11) * 0x1.0p-53;
  }
};

double wrap(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}

}  // namespace

FlareLineSet flare_lines(const ViewerProfile& viewer, FlareKind kind) {
  const bool corona = kind == FlareKind::corona;
  const double more = viewer.glasses ? 1.5 : 1.0;
  const int pairs = int(std::lround((corona ? 48 : 90) * more));
  // The corona's lines reach a few degrees; the halo's cover its ring (2-4.5 deg).
  const double longest = corona ? 4.0 * more : 6.0;
  SplitMix rng{std::uint64_t(viewer.seed) * 2 + (corona ? 0 : 1)};
  FlareLineSet set;
  const double sector = M_PI / pairs;  // pairs span half the circle; partners fill the other half
  for (int i = 0; i < pairs; ++i) {
    FlareLine line;
    line.angle_rad = sector * (i + 0.5 * rng.uniform());  // the lens flare filter tutorial: jittered within its sector
    line.length_deg = corona ? std::min((rng.uniform() + 0.2) * longest, longest) : longest;
    line.strength = rng.uniform();
    set.lines.push_back(line);
    line.angle_rad += M_PI;
    set.lines.push_back(line);
  }
  // Haze thins the lines (Matsuda and Ikedo): the weaker lines (strength
  // below the haze share) drown in the bloom, and the rest lose contrast
  // against the smooth floor in proportion. The pattern is otherwise the
  // same: haze 0 leaves it untouched.
  const double haze = std::clamp(viewer.haze, 0.0, 1.0);
  set.lines.erase(std::remove_if(set.lines.begin(), set.lines.end(),
                                 [&](const FlareLine& l) { return l.strength < haze; }),
                  set.lines.end());
  set.contrast *= 1.0 - haze;
  std::sort(set.lines.begin(), set.lines.end(),
            [](const FlareLine& a, const FlareLine& b) { return a.angle_rad < b.angle_rad; });
  return set;
}

double flare_pattern(const FlareLineSet& set, double dx, double dy, double ppd) {
  const double r = std::hypot(dx, dy);
  if (r == 0.0 || set.lines.empty()) return 0.0;
  const double t = r / ppd, width = set.width_deg * ppd;
  const double phi = wrap(std::atan2(dy, dx));
  // Lines farther than `reach` in angle are more than `width` away.
  const double reach = width >= r ? M_PI / 2.0 : std::asin(width / r);
  auto contribution = [&](const FlareLine& line) {
    double delta = std::abs(phi - line.angle_rad);
    delta = std::min(delta, kTwoPi - delta);
    if (delta >= M_PI / 2.0 || t >= line.length_deg) return 0.0;
    const double across = 1.0 - r * std::sin(delta) / width;
    const double along = 1.0 - (t / line.length_deg) * (t / line.length_deg);
    return across > 0.0 ? line.strength * across * across * along : 0.0;
  };
  double sum = 0.0;
  if (reach >= M_PI / 4.0) {
    for (const FlareLine& line : set.lines) sum += contribution(line);
    return sum;
  }
  // Lines with angles in [phi - reach, phi + reach], wrapping around 0.
  auto visit = [&](double from, double to) {
    auto it = std::lower_bound(set.lines.begin(), set.lines.end(), from,
                               [](const FlareLine& l, double a) { return l.angle_rad < a; });
    for (; it != set.lines.end() && it->angle_rad <= to; ++it) sum += contribution(*it);
  };
  const double from = phi - reach, to = phi + reach;
  visit(std::max(from, 0.0), std::min(to, kTwoPi));
  if (from < 0.0) visit(from + kTwoPi, kTwoPi);
  if (to > kTwoPi) visit(0.0, to - kTwoPi);
  return sum;
}

void apply_flare_lines(const FlareLineSet& lines, double ppd, const std::vector<cv::Mat*>& kernels,
                       double frame_ppd) {
  if (kernels.empty()) return;
  if (frame_ppd <= 0.0) frame_ppd = ppd;
  FlareLineSet set = lines;
  set.width_deg = std::max(set.width_deg, 1.5 / frame_ppd);
  const int sub = std::max(1, int(std::lround(frame_ppd / ppd)));  // frame pixels across a kernel pixel
  const cv::Size size = kernels.front()->size();
  const int cx = size.width / 2, cy = size.height / 2;
  // No line reaches past the longest: a pixel whose every sample lies
  // beyond it (one whole pixel of margin, far above rounding) sums zeros,
  // so its samples are not evaluated. A reduced kernel (the split engine's
  // tail, sub^2 samples a pixel) spans the whole frame and the lines only
  // its middle: most of its set-up time went there.
  double longest_deg = 0.0;
  for (const FlareLine& line : set.lines) longest_deg = std::max(longest_deg, line.length_deg);
  const double reach_px = longest_deg * ppd + 1.0;
  cv::Mat pattern(size, CV_64F);
  cv::Mat ring(size, CV_32S);
  cv::parallel_for_(cv::Range(0, size.height), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y)
      for (int x = 0; x < size.width; ++x) {
        const double dx = x - cx, dy = y - cy;
        double raw = 0.0;
        const double near_x = std::max(std::abs(dx) - 0.5, 0.0), near_y = std::max(std::abs(dy) - 0.5, 0.0);
        if (near_x * near_x + near_y * near_y < reach_px * reach_px)
          for (int sy = 0; sy < sub; ++sy)
            for (int sx = 0; sx < sub; ++sx)
              raw += flare_pattern(set, dx + (sx + 0.5) / sub - 0.5, dy + (sy + 0.5) / sub - 0.5, ppd);
        // Within 3 frame pixels of the centre every line overlaps: no pattern.
        const bool centre = std::hypot(dx, dy) * sub < 3.0;
        pattern.at<double>(y, x) = centre ? 1.0 : (1.0 - set.contrast) + set.contrast * raw / (sub * sub);
        ring.at<int>(y, x) = int(std::lround(std::hypot(dx, dy)));
      }
  });
  const int rings = int(std::lround(std::hypot(cx, cy))) + 1;
  for (cv::Mat* kernel : kernels) {
    CV_Assert(kernel->size() == size && kernel->type() == CV_64F);
    // Per ring: the kernel's energy, and with the pattern multiplied in.
    std::vector<double> plain(size_t(rings), 0.0), patterned(size_t(rings), 0.0);
    for (int y = 0; y < size.height; ++y)
      for (int x = 0; x < size.width; ++x) {
        const double k = kernel->at<double>(y, x);
        const size_t i = size_t(ring.at<int>(y, x));
        plain[i] += k;
        patterned[i] += k * pattern.at<double>(y, x);
      }
    for (int y = 0; y < size.height; ++y)
      for (int x = 0; x < size.width; ++x) {
        const size_t i = size_t(ring.at<int>(y, x));
        if (patterned[i] > 0.0) kernel->at<double>(y, x) *= pattern.at<double>(y, x) * plain[i] / patterned[i];
      }
  }
}

}  // namespace eyestream::glare
