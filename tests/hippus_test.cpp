// Hippus (glare/hippus.hpp) has the stated spectrum and size: power falling
// as 1/f over its band and none outside, RMS 0.1 mm at a 4 mm pupil, more
// for smaller pupils; a pure function of the seed. The spectrum is
// computed here (Hann-windowed periodograms averaged over half-overlapping
// segments) and its slope fitted in log-log.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <vector>

#include "glare/hippus.hpp"

namespace eyestream::glare {
namespace {

TEST(Hippus, HasTheStatedSpectrumAndSize) {
  const Hippus h(11);
  const double rate = 30.0;
  std::vector<double> x(size_t(4000 * rate));
  double sum2 = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    x[i] = h.offset_mm(4.0, double(i) / rate);
    sum2 += x[i] * x[i];
  }
  EXPECT_NEAR(std::sqrt(sum2 / double(x.size())), 0.1, 0.005) << "RMS at 4 mm";
  const int length = 4096;
  std::vector<double> power(length / 2 + 1, 0.0);
  for (size_t start = 0; start + length <= x.size(); start += length / 2) {
    cv::Mat segment(1, length, CV_64F), spectrum;
    for (int i = 0; i < length; ++i)
      segment.at<double>(i) = x[start + size_t(i)] * (0.5 - 0.5 * std::cos(2.0 * M_PI * i / length));
    cv::dft(segment, spectrum, cv::DFT_COMPLEX_OUTPUT);
    for (int k = 0; k <= length / 2; ++k) {
      const cv::Vec2d c = spectrum.at<cv::Vec2d>(k);
      power[size_t(k)] += c[0] * c[0] + c[1] * c[1];
    }
  }
  double sx = 0, sy = 0, sxx = 0, sxy = 0, total = 0, above = 0, below = 0;
  int n = 0;
  for (int k = 1; k <= length / 2; ++k) {
    const double f = k * rate / length, p = power[size_t(k)];
    total += p;
    if (f > 2.0) above += p;
    if (f < 0.03) below += p;
    if (f < 0.1 || f > 1.0) continue;
    sx += std::log10(f), sy += std::log10(p), sxx += std::log10(f) * std::log10(f), sxy += std::log10(f) * std::log10(p);
    ++n;
  }
  EXPECT_NEAR((n * sxy - sx * sy) / (n * sxx - sx * sx), -1.0, 0.2) << "1/f from 0.1 to 1 Hz";
  EXPECT_LT(above / total, 0.01) << "nothing above the band";
  EXPECT_LT(below / total, 0.03) << "nothing below it";
  EXPECT_GT(Hippus::rms_mm(2.5), Hippus::rms_mm(4.0));
  EXPECT_GT(Hippus::rms_mm(4.0), Hippus::rms_mm(7.0));
  EXPECT_NEAR(Hippus::rms_mm(9.0), 0.0, 1e-12) << "none at full dilation";
  EXPECT_EQ(Hippus(11).noise(123.4), h.noise(123.4));
  EXPECT_NE(Hippus(12).noise(123.4), h.noise(123.4));
}

}  // namespace
}  // namespace eyestream::glare
