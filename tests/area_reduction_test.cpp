// AreaReduction (retina/area_reduction.hpp) against OpenCV's cv::resize
// with INTER_AREA, bit for bit: the retina stage's own reductions at 1080p
// and 720p (0.31 and 0.47 site a pixel), factors that are not whole each
// way up to the most taps it takes, one axis whole and the other not, one
// output column, a region of a larger image and an exactly sized one,
// values from 1e-9 to 1e9 cd/m^2 in one image with zeros, an infinity and
// a NaN; whole factors each way (OpenCV's other path: `fast`'s grid); and
// the cases it hands to cv::resize (enlargement, one channel, reductions
// past its taps).
#include "retina/area_reduction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <opencv2/imgproc.hpp>

namespace eyestream::retina {
namespace {

cv::Mat scene(cv::Size size, int type, cv::RNG& random) {
  cv::Mat big(size.height + 3, size.width + 5, type);
  random.fill(big, cv::RNG::UNIFORM, 0.0, 1e5);
  const int cn = big.channels();
  big.ptr<float>(1)[2 * cn] = 1e9f;
  big.ptr<float>(1)[2 * cn + 1] = 1e-9f;
  big.ptr<float>(2)[3 * cn] = 0.0f;
  big.ptr<float>(size.height / 2)[cn * (size.width / 2)] = INFINITY;
  big.ptr<float>(size.height)[cn * size.width - 1] = NAN;
  return big(cv::Rect(cv::Point(2, 1), size));  // rows with gaps between them
}

// Bit for bit as cv::resize, on `frame` (a region of a larger image) and
// on an exactly sized copy (a read past its last pixel is the sanitizer
// build's error); `own` says whether AreaReduction's loop makes it.
void expect_as_opencv(const cv::Mat& frame, cv::Size to, bool own) {
  ASSERT_EQ(AreaReduction(frame.size(), to).replaces_opencv(), own) << frame.size() << " to " << to;
  cv::Mat want;
  cv::resize(frame, want, to, 0, 0, cv::INTER_AREA);
  for (const cv::Mat& in : {frame, frame.clone()}) {
    cv::Mat got;
    AreaReduction(frame.size(), to).apply(in, got);
    ASSERT_EQ(got.size(), want.size()) << frame.size() << " to " << to;
    ASSERT_EQ(got.type(), frame.type());
    for (int y = 0; y < got.rows; ++y)
      ASSERT_EQ(std::memcmp(got.ptr(y), want.ptr(y), size_t(got.cols) * got.elemSize()), 0)
          << frame.size() << " to " << to << " row " << y << (in.isContinuous() ? ", exactly sized" : "");
  }
}

TEST(AreaReduction, IsCvResizesAreaMeanBitForBit) {
  cv::RNG random(5);
  const std::pair<cv::Size, cv::Size> cases[] = {
      {{1920, 1080}, {595, 335}},  // balanced's grid at 1080p
      {{1280, 720}, {601, 338}},   // and at 720p
      {{640, 360}, {320, 181}},    // near a half, not one
      {{97, 61}, {15, 9}},         // 6.5 and 6.8: the most taps, 8
      {{23, 11}, {10, 5}},         // 2.3 and 2.2: four taps where 2.3 covers 4
      {{100, 50}, {33, 25}},       // the rows a whole factor, the columns not
      {{100, 50}, {50, 17}},       // the columns a whole factor, the rows not
      {{7, 5}, {3, 2}},
      {{5, 7}, {1, 3}},  // one output column
  };
  for (const auto& [from, to] : cases) expect_as_opencv(scene(from, CV_32FC3, random), to, true);
}

TEST(AreaReduction, IsCvResizesWholeFactorPathBitForBit) {
  cv::RNG random(8);
  const std::pair<cv::Size, cv::Size> cases[] = {
      {{1920, 1080}, {480, 270}},  // fast's grid at 1080p: 16 values, four groups of a row each
      {{96, 60}, {24, 15}},        // the same factor, small
      {{99, 60}, {33, 20}},        // 3 each way: groups of four across rows, one value left
      {{40, 30}, {20, 15}},        // 2 each way: one group (halve_frame.hpp's)
      {{40, 30}, {40, 15}},        // 1 and 2: two values, none in a group
      {{60, 30}, {20, 30}},        // 3 and 1: three values, none in a group
      {{40, 30}, {10, 30}},        // 4 and 1: one group within a row
      {{64, 48}, {8, 6}},          // 8 each way: 64 values, past the general path's taps
      {{5, 9}, {1, 1}},            // 5 and 9: one output pixel, the row's last
  };
  for (const auto& [from, to] : cases) expect_as_opencv(scene(from, CV_32FC3, random), to, true);
}

TEST(AreaReduction, LeavesEnlargementsAndOtherTypesToOpenCv) {
  cv::RNG random(6);
  expect_as_opencv(scene({96, 60}, CV_32FC3, random), {100, 30}, false);  // wider
  expect_as_opencv(scene({97, 61}, CV_32FC3, random), {13, 7}, false);   // 7.5 across: past the taps
  expect_as_opencv(scene({96, 60}, CV_32FC1, random), {31, 17}, true);   // (made by cv::resize at apply())
}

TEST(AreaReduction, GivesTheSameValuesWhateverTheThreads) {
  cv::RNG random(7);
  const cv::Mat frame = scene({1920, 1080}, CV_32FC3, random);
  for (const cv::Size to : {cv::Size(595, 335), cv::Size(480, 270)}) {  // balanced's grid, and fast's (whole)
    const AreaReduction reduction(frame.size(), to);
    const int threads = cv::getNumThreads();
    cv::Mat one, many;
    cv::setNumThreads(1);
    reduction.apply(frame, one);
    cv::setNumThreads(7);
    reduction.apply(frame, many);
    cv::setNumThreads(threads);
    for (int y = 0; y < one.rows; ++y)
      ASSERT_EQ(std::memcmp(one.ptr(y), many.ptr(y), size_t(one.cols) * one.elemSize()), 0) << to << " row " << y;
  }
}

}  // namespace
}  // namespace eyestream::retina
