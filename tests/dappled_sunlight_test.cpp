// The dappled-sunlight scene: each gap's light follows a 1/f fluctuation
// (Matsuda and Ikedo eqs. 9-11). The spectra are computed here (a Hann-
// windowed periodogram averaged over half-overlapping segments) and their
// log-log slope fitted by least squares.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "io/exr_file.hpp"
#include "samples/chaos_fluctuation.hpp"
#include "samples/dappled_sunlight.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

// Slope of log10 power against log10 frequency over [f_low, f_high]
// cycles per sample, from segments of `length` samples.
double spectral_slope(const std::vector<double>& x, int length, double f_low, double f_high) {
  std::vector<double> power(size_t(length / 2 + 1), 0.0);
  for (size_t start = 0; start + size_t(length) <= x.size(); start += size_t(length / 2)) {
    double mean = 0.0;
    for (int i = 0; i < length; ++i) mean += x[start + size_t(i)] / length;
    cv::Mat segment(1, length, CV_64F), spectrum;
    for (int i = 0; i < length; ++i)
      segment.at<double>(i) = (x[start + size_t(i)] - mean) * (0.5 - 0.5 * std::cos(2.0 * M_PI * i / length));
    cv::dft(segment, spectrum, cv::DFT_COMPLEX_OUTPUT);
    for (int k = 0; k <= length / 2; ++k) {
      const cv::Vec2d c = spectrum.at<cv::Vec2d>(k);
      power[size_t(k)] += c[0] * c[0] + c[1] * c[1];
    }
  }
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (int k = 1; k <= length / 2; ++k) {
    const double f = double(k) / length;
    if (f < f_low || f > f_high) continue;
    const double lx = std::log10(f), ly = std::log10(power[size_t(k)]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly, ++n;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

TEST(DappledSunlight, TheChaosOrbitHasAOneOverFSpectrum) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    samples::ChaosFluctuation orbit(seed);
    std::vector<double> s(1 << 16);
    for (double& v : s) {
      v = orbit.next();
      ASSERT_TRUE(v > 0.0 && v < 1.0) << v;
    }
    const double slope = spectral_slope(s, 2048, 1.0 / 256, 1.0 / 8);
    EXPECT_NEAR(slope, -1.0, 0.2) << "seed " << seed;
    samples::ChaosFluctuation again(seed), other(seed + 10);
    int differ = 0;
    for (int i = 0; i < 1000; ++i) {
      ASSERT_EQ(again.next(), s[size_t(i)]) << "the same seed repeats the orbit";
      differ += other.next() != s[size_t(i)];
    }
    EXPECT_GT(differ, 990) << "another seed, another orbit";
  }
}

// The total light of the scene's frames minus its still canopy is the sum
// of the gaps' light: through the command line, two minutes at 30 frames/s
// (a 48x27 frame) it has a 1/f spectrum; at 60 frames/s each wind step
// holds two frames.
TEST(DappledSunlight, TheFramesLightFluctuatesAsOneOverF) {
  test::ScratchDir dir;
  const auto r = test::run_eyestream("sample dappled-sunlight -o " + dir / "d30" +
                                     " --width 48 --height 27 --fps 30 --duration 120");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto total = [&](const std::string& folder, int n) {
    char name[32];
    std::snprintf(name, sizeof name, "/frames/%05d.exr", n);
    const cv::Mat rgb = io::read_exr(folder + name, 1 << 20).rgb;
    const cv::Scalar sum = cv::sum(rgb);
    return 0.2126 * sum[0] + 0.7152 * sum[1] + 0.0722 * sum[2];  // Rec.709 Y
  };
  std::vector<double> light;
  for (int n = 0; n < 3600; ++n) light.push_back(total(dir / "d30", n));
  EXPECT_NEAR(spectral_slope(light, 512, 1.0 / 256, 1.0 / 8), -1.0, 0.2);
  // The light moves: the sun's share is most of the frame's and varies.
  const auto [low, high] = std::minmax_element(light.begin(), light.end());
  EXPECT_GT(*high / *low, 1.5);

  ASSERT_EQ(test::run_eyestream("sample dappled-sunlight -o " + dir / "d60" +
                                " --width 48 --height 27 --fps 60 --duration 0.5")
                .exit_code,
            0);
  for (int n = 0; n < 30; n += 2) {
    EXPECT_EQ(total(dir / "d60", n), total(dir / "d60", n + 1)) << "one wind step, frames " << n << " and " << n + 1;
    EXPECT_NEAR(total(dir / "d60", n), light[size_t(n / 2)], 1e-3 * light[size_t(n / 2)])
        << "the same wind step at 30 frames/s";
  }
}

}  // namespace
}  // namespace eyestream
