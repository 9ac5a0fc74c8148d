// Flare lines (Spencer et al. 1995 sec. 3.2, the lens flare filter tutorial,
// Matsuda and Ikedo): detail
// in the PSF without changing its radial profile or its energy.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "glare/eye_optics.hpp"
#include "glare/flare_lines.hpp"
#include "glare/psf_kernel.hpp"

namespace eyestream::glare {
namespace {

constexpr int kW = 200, kH = 120;
constexpr double kPpd = 20.0;  // 10 x 6 deg

const ComponentKernels& plain() {
  static const ComponentKernels k = build_component_kernels(kW, kH, kPpd, EyeOptics());
  return k;
}

const ComponentKernels& streaked() {
  static const ComponentKernels k = build_component_kernels(kW, kH, kPpd, EyeOptics({}, PsfModel::vos, true));
  return k;
}

// The kernel's values on the pixels whose centres lie within 0.5 px of radius r.
std::vector<double> ring(const cv::Mat& k, double r) {
  std::vector<double> v;
  const int cx = k.cols / 2, cy = k.rows / 2;
  for (int y = 0; y < k.rows; ++y)
    for (int x = 0; x < k.cols; ++x)
      if (std::abs(std::hypot(x - cx, y - cy) - r) < 0.5) v.push_back(k.at<double>(y, x));
  return v;
}

double sum(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s;
}

// Standard deviation over mean.
double variation(const std::vector<double>& v) {
  const double mean = sum(v) / double(v.size());
  double sq = 0;
  for (double x : v) sq += (x - mean) * (x - mean);
  return std::sqrt(sq / double(v.size())) / mean;
}

TEST(FlareLines, EveryRingKeepsItsEnergySoTheRadialProfileAndTotalAreUnchanged) {
  const cv::Mat* a[5] = {&plain().inner, &plain().outer, &plain().halo[0], &plain().halo[1], &plain().halo[2]};
  const cv::Mat* b[5] = {&streaked().inner, &streaked().outer, &streaked().halo[0], &streaked().halo[1],
                         &streaked().halo[2]};
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(cv::sum(*b[i])[0] / cv::sum(*a[i])[0], 1.0, 1e-9) << "component " << i;
    for (double r : {5.0, 20.0, 60.0, 110.0}) EXPECT_NEAR(sum(ring(*b[i], r)) / sum(ring(*a[i], r)), 1.0, 1e-9);
  }
  EXPECT_EQ(cv::norm(plain().core, streaked().core, cv::NORM_INF), 0.0) << "the unscattered core has no lines";
}

TEST(FlareLines, TheCoronaAndTheHaloShowStreaks) {
  // 1 deg (corona) and 3 deg (the halo's ring): smooth without lines,
  // streaked with them.
  EXPECT_LT(variation(ring(plain().inner, 20.0)), 0.05);
  EXPECT_GT(variation(ring(streaked().inner, 20.0)), 0.3);
  EXPECT_LT(variation(ring(plain().halo[1], 60.0)), 0.05);
  EXPECT_GT(variation(ring(streaked().halo[1], 60.0)), 0.3);
  // Two sets: the corona's streaks are not the halo's.
  const std::vector<double> corona = ring(streaked().outer, 60.0), halo = ring(streaked().halo[1], 60.0);
  double dot = 0, nc = 0, nh = 0;
  const double mc = sum(corona) / double(corona.size()), mh = sum(halo) / double(halo.size());
  for (size_t i = 0; i < corona.size(); ++i) {
    dot += (corona[i] - mc) * (halo[i] - mh);
    nc += (corona[i] - mc) * (corona[i] - mc);
    nh += (halo[i] - mh) * (halo[i] - mh);
  }
  EXPECT_LT(std::abs(dot / std::sqrt(nc * nh)), 0.5) << "correlation of the two sets on the 3 deg ring";
}

TEST(FlareLines, ThePatternIsTheViewersOwn) {
  const ComponentKernels again = build_component_kernels(kW, kH, kPpd, EyeOptics({}, PsfModel::vos, true));
  EXPECT_EQ(cv::norm(again.inner, streaked().inner, cv::NORM_INF), 0.0) << "same seed, same pattern";
  ViewerProfile other;
  other.seed = 2;
  const ComponentKernels k = build_component_kernels(kW, kH, kPpd, EyeOptics(other, PsfModel::vos, true));
  const std::vector<double> mine = ring(streaked().inner, 20.0), theirs = ring(k.inner, 20.0);
  double largest = 0;
  for (size_t i = 0; i < mine.size(); ++i) largest = std::max(largest, std::abs(mine[i] - theirs[i]));
  EXPECT_GT(largest, 0.5 * sum(mine) / double(mine.size())) << "another viewer's streaks lie elsewhere";
}

TEST(FlareLines, GlassesGiveMoreAndLongerLines) {
  ViewerProfile bare, glasses;
  glasses.glasses = true;
  const FlareLineSet a = flare_lines(bare, FlareKind::corona), b = flare_lines(glasses, FlareKind::corona);
  EXPECT_GE(double(b.lines.size()), 1.4 * double(a.lines.size()));
  // No bare-eyed corona line reaches 4.5 deg; some of the glasses' do.
  double reach_a = 0, reach_b = 0;
  for (int i = 0; i < 3600; ++i) {
    const double phi = i * 2 * M_PI / 3600, r = 4.5 * kPpd;
    reach_a = std::max(reach_a, flare_pattern(a, r * std::cos(phi), r * std::sin(phi), kPpd));
    reach_b = std::max(reach_b, flare_pattern(b, r * std::cos(phi), r * std::sin(phi), kPpd));
  }
  EXPECT_EQ(reach_a, 0.0);
  EXPECT_GT(reach_b, 0.0);
}

TEST(FlareLines, BrighterSourcesShowMoreStreaksAboveTheDisplayPeak) {
  // On the 2 deg ring, the share of directions where a source of luminance L
  // lays more than the display peak rises gradually with L (line by line),
  // where the smooth PSF crosses from none to all at once.
  const double peak = 100.0;
  auto share_above = [&](const cv::Mat& k, double l) {
    const std::vector<double> v = ring(k, 40.0);
    int above = 0;
    for (double x : v) above += l * x > peak;
    return double(above) / double(v.size());
  };
  const double mean = sum(ring(plain().outer, 40.0)) / double(ring(plain().outer, 40.0).size());
  const double l_mean = peak / mean;  // where the smooth ring reaches the peak
  double previous = 0;
  int partial = 0;
  for (double f = 0.25; f <= 4.0; f *= 1.25) {
    const double s = share_above(streaked().outer, f * l_mean);
    EXPECT_GE(s, previous);
    partial += s > 0.05 && s < 0.95;
    previous = s;
  }
  EXPECT_GE(partial, 5) << "streak by streak over more than a factor of 2 in luminance";
  EXPECT_EQ(share_above(plain().outer, 0.8 * l_mean), 0.0);
  EXPECT_EQ(share_above(plain().outer, 1.25 * l_mean), 1.0);
}

}  // namespace
}  // namespace eyestream::glare
