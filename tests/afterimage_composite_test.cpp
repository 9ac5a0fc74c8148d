// The afterimage composite (retina/afterimage_composite.hpp) against its
// definition written out here per pixel with OpenCV's own matrix types:
// the vectorised rows give the same bits, pixels at rest are the tone
// curve's unchanged, and reduced maps are read as cv::resize INTER_LINEAR
// enlarges them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <opencv2/imgproc.hpp>

#include "retina/afterimage_composite.hpp"
#include "retina/cone_space.hpp"

namespace eyestream::retina {
namespace {

// Random maps with about a third of their pixels exactly at rest (+0 or -0).
cv::Mat map_with_rest(cv::Size size, std::uint64_t seed, double lo, double hi) {
  cv::RNG rng(seed);
  cv::Mat m(size, CV_32FC3);
  rng.fill(m, cv::RNG::UNIFORM, lo, hi);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x)
      if (rng.uniform(0, 3) == 0) m.at<cv::Vec3f>(y, x) = rng.uniform(0, 2) ? cv::Vec3f(0, 0, 0) : cv::Vec3f(-0.0f, 0, -0.0f);
  return m;
}

// The definition: out = to_rgb ((1 + g) to_lms j) + H b, or j where g and b are 0.
cv::Vec3f defined(const cv::Vec3f& j, const cv::Vec3f& g, const cv::Vec3f& b) {
  if (g == cv::Vec3f(0, 0, 0) && b == cv::Vec3f(0, 0, 0)) return j;
  const cv::Vec3f lms = rgb_to_lms_f() * j;
  return lms_to_rgb_f() * (lms + lms.mul(g)) + afterimage_matrix_f() * b;
}

// Where pixel i of `full` reads a map of `reduced` pixels (cv::resize's
// INTER_LINEAR mapping, borders replicated).
void tap(int i, int full, int reduced, int& lo, int& hi, float& w) {
  const float s = float(reduced) / float(full);
  const float g = std::clamp((float(i) + 0.5f) * s - 0.5f, 0.0f, float(reduced - 1));
  lo = int(g);
  hi = std::min(lo + 1, reduced - 1);
  w = g - float(lo);
}

TEST(AfterimageComposite, FrameSizedMapsGiveTheDefinitionsBits) {
  const cv::Size size(203, 37);  // odd widths: the vector loops' tails
  const cv::Mat j = map_with_rest(size, 1, 0.0, 1.0);
  const cv::Mat g = map_with_rest(size, 2, -0.5, 0.5), b = map_with_rest(size, 3, -0.05, 0.05);
  cv::Mat out;
  composite_afterimages(j, g, b, out);
  int at_rest = 0;
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      const cv::Vec3f want = defined(j.at<cv::Vec3f>(y, x), g.at<cv::Vec3f>(y, x), b.at<cv::Vec3f>(y, x));
      const cv::Vec3f got = out.at<cv::Vec3f>(y, x);
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(std::memcmp(&want[c], &got[c], sizeof(float)), 0) << x << "," << y << " " << want[c] << " " << got[c];
      at_rest += g.at<cv::Vec3f>(y, x) == cv::Vec3f(0, 0, 0) && b.at<cv::Vec3f>(y, x) == cv::Vec3f(0, 0, 0);
    }
  EXPECT_GT(at_rest, 0) << "some pixels at rest";
  // In place, as the retina stage may call it.
  cv::Mat in_place = j.clone();
  composite_afterimages(in_place, g, b, in_place);
  EXPECT_EQ(cv::norm(in_place, out, cv::NORM_INF), 0.0);
}

TEST(AfterimageComposite, ReducedMapsAreReadBilinearlyAsCvResizeEnlargesThem) {
  const cv::Size size(203, 117), reduced(51, 30);
  const cv::Mat j = map_with_rest(size, 4, 0.0, 1.0);
  const cv::Mat g = map_with_rest(reduced, 5, -0.5, 0.5), b = map_with_rest(reduced, 6, -0.05, 0.05);
  cv::Mat out;
  composite_afterimages(j, g, b, out);
  // The definition with the maps enlarged per pixel, bit for bit.
  for (int y = 0; y < size.height; ++y) {
    int y0, y1;
    float fy;
    tap(y, size.height, reduced.height, y0, y1, fy);
    for (int x = 0; x < size.width; ++x) {
      int x0, x1;
      float fx;
      tap(x, size.width, reduced.width, x0, x1, fx);
      const auto read = [&](const cv::Mat& m) {
        return (m.at<cv::Vec3f>(y0, x0) * (1.0f - fx) + m.at<cv::Vec3f>(y0, x1) * fx) * (1.0f - fy) +
               (m.at<cv::Vec3f>(y1, x0) * (1.0f - fx) + m.at<cv::Vec3f>(y1, x1) * fx) * fy;
      };
      const cv::Vec3f want = defined(j.at<cv::Vec3f>(y, x), read(g), read(b));
      const cv::Vec3f got = out.at<cv::Vec3f>(y, x);
      for (int c = 0; c < 3; ++c) ASSERT_EQ(std::memcmp(&want[c], &got[c], sizeof(float)), 0) << x << "," << y;
    }
  }
  // One thread gives the same bits.
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  cv::Mat one;
  composite_afterimages(j, g, b, one);
  cv::setNumThreads(threads);
  EXPECT_EQ(std::memcmp(one.data, out.data, out.total() * out.elemSize()), 0);
  // And against OpenCV's own enlargement, to its rounding.
  cv::Mat g_full, b_full, expected;
  cv::resize(g, g_full, size, 0, 0, cv::INTER_LINEAR);
  cv::resize(b, b_full, size, 0, 0, cv::INTER_LINEAR);
  double worst = 0.0;
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      const cv::Vec3f want = defined(j.at<cv::Vec3f>(y, x), g_full.at<cv::Vec3f>(y, x), b_full.at<cv::Vec3f>(y, x));
      worst = std::max(worst, cv::norm(want - out.at<cv::Vec3f>(y, x), cv::NORM_INF));
    }
  EXPECT_LT(worst, 1e-4);  // a map one pixel off is 0.1 off
}

}  // namespace
}  // namespace eyestream::retina
