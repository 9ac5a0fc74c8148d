// The shaped-lamps scene against its stated geometry and timing, computed
// here from the numbers in its description: the bar's length and width,
// the beacon's cos^8 beam turning 1.5 times a second, the cyclist's 4 deg/s,
// at 30 and 60 frames/s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "io/exr_file.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

constexpr int kWidth = 640, kHeight = 360;
constexpr double kPpd = kWidth / 29.3;  // the default viewing condition

cv::Mat frame(const std::string& dir, int n) {
  char name[32];
  std::snprintf(name, sizeof name, "/frames/%05d.exr", n);
  cv::Mat rgb = io::read_exr(dir + name, 1 << 22).rgb, y;
  cv::transform(rgb, y, cv::Matx13f(0.2126f, 0.7152f, 0.0722f));
  return y;
}

// Light (luminance times pixels) inside a rectangle.
double light(const cv::Mat& y, cv::Rect r) { return cv::sum(y(r))[0]; }

TEST(ShapedLamps, TheBarTheBeaconAndTheCyclistAreAsStated) {
  test::ScratchDir dir;
  for (const char* fps : {"30", "60"})
    ASSERT_EQ(test::run_eyestream("sample shaped-lamps -o " + dir / fps + " --fps " + fps + " --duration 1.1").exit_code,
              0);
  const std::string d30 = dir / "30", d60 = dir / "60";
  // The bar: the pixels over half its luminance span 1.5 deg by 0.08 deg.
  const cv::Mat y0 = frame(d30, 0);
  cv::Mat bar = y0(cv::Rect(0, 0, kWidth / 2 + 40, kHeight / 2)) > 0.5 * y0.at<float>(int(0.25 * kHeight), int(0.3 * kWidth));
  const cv::Rect box = cv::boundingRect(bar);
  EXPECT_NEAR(box.width, 1.5 * kPpd, 1.5);
  EXPECT_LE(box.height, 3);
  // The beacon: its light over time follows 0.01 + max(0, cos(2 pi 1.5 t))^8.
  const cv::Rect beacon(int(0.72 * kWidth) - 8, kHeight / 2 - 8, 16, 16);
  const auto beam = [](double t) {
    const double c = std::cos(2.0 * M_PI * 1.5 * t);
    return 0.01 + (c > 0 ? std::pow(c, 8.0) : 0.0);
  };
  const double per_unit = light(y0, beacon) / beam(0.0);
  for (int n = 1; n < 30; ++n)
    EXPECT_NEAR(light(frame(d30, n), beacon) / beam(n / 30.0), per_unit, 0.01 * per_unit) << "frame " << n;
  // The cyclist: the centroid of the lamp's light moves 4 deg/s; frame 2n
  // at 60 frames/s is frame n at 30.
  const auto lamp_x = [](const cv::Mat& y) {
    const cv::Mat band = y(cv::Rect(0, int(0.6 * kHeight), kWidth, int(0.15 * kHeight)));
    double peak;
    cv::minMaxLoc(band, nullptr, &peak);
    double sum = 0, sum_x = 0;
    for (int r = 0; r < band.rows; ++r)
      for (int c = 0; c < band.cols; ++c)
        if (band.at<float>(r, c) > 0.01 * peak) sum += band.at<float>(r, c), sum_x += c * band.at<float>(r, c);
    return sum_x / sum;
  };
  const double x0 = lamp_x(y0);
  EXPECT_NEAR(x0, 0.1 * kWidth, 1.0);  // (pixel centres at +0.5)
  EXPECT_NEAR(lamp_x(frame(d30, 30)) - x0, 4.0 * kPpd, 0.5);
  EXPECT_NEAR(lamp_x(frame(d60, 30)) - x0, 2.0 * kPpd, 0.5);
  EXPECT_NEAR(lamp_x(frame(d60, 60)), lamp_x(frame(d30, 30)), 1e-3);
}

}  // namespace
}  // namespace eyestream
