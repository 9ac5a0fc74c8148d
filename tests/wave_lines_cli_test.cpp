// The wave-optics lines through the command line (--flare-model wave), on
// the shaped-lamps sample at 30 and 60 frames/s and two resolutions: the
// lines are the difference from a run without lines around the beacon;
// they are the same on one thread as on two, agree between frame rates at the same moment, and
// change over a second (hippus, the drifting vitreous); far from every
// light there are none.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <opencv2/core.hpp>
#include <string>

#include "io/exr_file.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

cv::Mat green(const std::string& pattern, int n) {
  char name[256];
  std::snprintf(name, sizeof name, pattern.c_str(), n);
  std::vector<cv::Mat> c;
  cv::split(io::read_exr(name, 1 << 22).rgb, c);
  return c[1];
}

double correlation(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat ma, sa, mb, sb;
  cv::meanStdDev(a, ma, sa);
  cv::meanStdDev(b, mb, sb);
  return cv::mean((a - ma.at<double>(0)).mul(b - mb.at<double>(0)))[0] / (sa.at<double>(0) * sb.at<double>(0));
}

TEST(WaveLinesCli, LinesRepeatAgreeAcrossFrameRatesAndChangeOverASecond) {
  test::ScratchDir dir;
  for (const int width : {320, 400}) {
    if (test::kSanitized && width != 320) continue;  // 182 s for both sizes under ASan
    const int height = width * 9 / 16;
    const double ppd = width / 29.3;
    const cv::Rect beacon(int(0.72 * width - 3 * ppd), int(0.5 * height - 3 * ppd), int(6 * ppd), int(6 * ppd));
    cv::Mat lines[2][2];  // [fps 30, 60][t 0.5 s, 1.5 s]
    for (const int fps : {30, 60}) {
      const std::string scene = dir / ("s" + std::to_string(width) + "_" + std::to_string(fps));
      ASSERT_EQ(test::run_eyestream("sample shaped-lamps -o " + scene + " --width " + std::to_string(width) +
                                    " --height " + std::to_string(height) + " --fps " + std::to_string(fps) +
                                    " --duration 1.6")
                    .exit_code,
                0);
      const bool one_thread = width == 320 && fps == 30;  // (the thread count's check, once)
      for (const std::string& model : {std::string("wave"), std::string("none"), std::string("wave1")}) {
        if (model == "wave1" && !one_thread) continue;
        const std::string options = model == "none" ? " --no-flare-lines"
                                    : model == "wave" ? " --flare-model wave"
                                                      : " --flare-model wave --threads 1";
        const auto r = test::run_eyestream("run -i " + scene + "/frames -g " + scene + "/gaze.csv -o " + scene + "/" +
                                           model + "/%05d.exr --exr-compression none" + options);
        ASSERT_EQ(r.exit_code, 0) << r.output;
      }
      const int at[2] = {fps / 2, 3 * fps / 2};
      for (int i = 0; i < 2; ++i) {
        const cv::Mat wave = green(scene + "/wave/%05d.exr", at[i]), none = green(scene + "/none/%05d.exr", at[i]);
        if (one_thread) {
          EXPECT_EQ(cv::norm(wave, green(scene + "/wave1/%05d.exr", at[i]), cv::NORM_INF), 0.0)
              << "the same on one thread";
        }
        lines[fps / 60][i] = (wave - none)(beacon);
        // Far from every light (the top right corner): no lines.
        const cv::Rect corner(width - int(ppd), 0, int(ppd), int(ppd));
        EXPECT_EQ(cv::norm(wave(corner), none(corner), cv::NORM_INF), 0.0);
      }
      EXPECT_GT(cv::norm(lines[fps / 60][0], cv::NORM_INF), 0.0) << "lines round the beacon";
    }
    const double rates = correlation(lines[0][0], lines[1][0]);
    const double second = correlation(lines[0][0], lines[0][1]);
    std::printf("%d px: lines at 0.5 s, 30 against 60 frames/s %.3f; at 0.5 against 1.5 s %.3f\n", width, rates,
                second);
    EXPECT_GT(rates, 0.9);
    EXPECT_LT(second, 0.7);
  }
}

}  // namespace
}  // namespace eyestream
