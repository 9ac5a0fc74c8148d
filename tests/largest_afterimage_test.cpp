// RetinaState::largest_afterimage, which the retina stage asks of the
// whole grid to learn whether it rests, gives what afterimages() reports
// as the largest value of its maps, without making them: exactly, after a
// flash, in both precisions, with a visibility fall-off, and the largest
// |value| read off the maps; and 0 at rest.
#include <gtest/gtest.h>

#include <algorithm>

#include "retina/retina_state.hpp"
#include "retina/tone_curve.hpp"

namespace eyestream::retina {
namespace {

TEST(LargestAfterimage, IsTheLargestValueOfTheMapsAfterAFlashAndZeroAtRest) {
  for (const bool double_precision : {false, true}) {
    const int type = double_precision ? CV_64FC3 : CV_32FC3;
    const cv::Size grid(48, 32);
    RetinaState state(grid, PhotoreceptorParams(), double_precision);
    const ToneCurve curve(1.0, ToneCurveParams());
    const cv::Mat dim(grid, type, cv::Scalar(10.0, 8.0, 5.0));
    cv::Mat visibility(grid, CV_32F);
    for (int y = 0; y < grid.height; ++y)
      for (int x = 0; x < grid.width; ++x) visibility.at<float>(y, x) = 1.0f - 0.015f * float(x + y);
    state.rest(dim, curve);
    EXPECT_EQ(state.largest_afterimage(AfterimageOptions(), visibility), 0.0f);
    EXPECT_EQ(state.afterimages(AfterimageOptions(), visibility).largest, 0.0f);
    cv::Mat flash = dim.clone();
    flash(cv::Rect(30, 4, 10, 8)).setTo(cv::Scalar(2e4, 1.5e4, 3e3));
    state.step(flash, curve, 0.5);
    state.step(dim, curve, 0.2);  // the flash gone: afterimages on the dim field
    for (const AfterimageOptions& o : {AfterimageOptions(), AfterimageOptions{true, false}, AfterimageOptions{false, true}}) {
      const float largest = state.largest_afterimage(o, visibility);
      EXPECT_GT(largest, 0.0f);
      const AfterimageMaps maps = state.afterimages(o, visibility);
      EXPECT_EQ(largest, maps.largest) << (double_precision ? "double" : "float");
      // Read off the maps themselves, not from the loop that fills them.
      const double in_maps = std::max(cv::norm(maps.gain_excess, cv::NORM_INF), cv::norm(maps.bleach, cv::NORM_INF));
      EXPECT_EQ(double(largest), in_maps);
    }
  }
}

}  // namespace
}  // namespace eyestream::retina
