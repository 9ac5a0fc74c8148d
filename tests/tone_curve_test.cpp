#include "retina/tone_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "retina/tone_map.hpp"
#include "tests/test_support.hpp"

namespace eyestream::retina {
namespace {

const ToneCurveParams kDefaults;

TEST(ToneCurve, AdaptedBackgroundRestsOnThePlateau) {
  // Jacobs et al. 2015 eq. 2: R(Ib) = M(Ib) when adapted to Ib.
  for (double a : {-5.0, -2.0, 0.0, 1.5, 3.0, 6.0}) {
    const ToneCurve curve(a, kDefaults);
    EXPECT_NEAR(curve.response(float(std::pow(10.0, a))), plateau(a, kDefaults), 1e-5) << a;
  }
}

TEST(ToneCurve, PlateauRisesFromDarkToDaylightAsDocumented) {
  EXPECT_NEAR(plateau(-3.0, kDefaults), 0.034, 5e-4);
  EXPECT_NEAR(plateau(0.0, kDefaults), 0.097, 5e-4);
  EXPECT_NEAR(plateau(2.0, kDefaults), 0.260, 5e-4);
  EXPECT_NEAR(plateau(4.0, kDefaults), 0.372, 5e-4);
  for (double a = -8; a < 10; a += 0.25) EXPECT_LT(plateau(a, kDefaults), plateau(a + 0.25, kDefaults));
}

TEST(ToneCurve, ResponseIsMonotonicAndBoundedOverTheWholeRange) {
  for (double a : {-6.0, -1.0, 2.0, 9.0}) {
    const ToneCurve curve(a, kDefaults);
    float previous = 0.0f;
    for (double log_l = -8; log_l <= 11; log_l += 0.01) {
      const float r = curve.response(float(std::pow(10.0, log_l)));
      ASSERT_TRUE(std::isfinite(r));
      ASSERT_GE(r, previous) << "a=" << a << " log L=" << log_l;
      ASSERT_LE(r, 1.0f);
      previous = r;
    }
    EXPECT_GT(previous, 0.9f);  // two or more log units above the adaptation level
  }
}

TEST(ToneCurve, DegenerateInputsStayFinite) {
  const ToneCurve curve(0.0, kDefaults);
  EXPECT_EQ(curve.response(0.0f), 0.0f);
  EXPECT_EQ(curve.response(-5.0f), 0.0f);
  EXPECT_EQ(curve.response(std::numeric_limits<float>::quiet_NaN()), 0.0f);
  EXPECT_EQ(curve.response(std::numeric_limits<float>::infinity()), 1.0f);
  EXPECT_EQ(curve.response(std::numeric_limits<float>::denorm_min()), 0.0f);
}

TEST(ToneCurve, BrighterAdaptationDarkensTheSameStimulus) {
  EXPECT_GT(ToneCurve(0.0, kDefaults).response(10.0f), ToneCurve(2.0, kDefaults).response(10.0f));
}

TEST(ToneMap, KeepsColourRatiosAndBlanksBadPixels) {
  cv::Mat frame = test::constant_frame(3, 1, {20.0f, 10.0f, 5.0f});
  frame.at<cv::Vec3f>(0, 1) = cv::Vec3f(std::numeric_limits<float>::quiet_NaN(), 1, 1);
  frame.at<cv::Vec3f>(0, 2) = cv::Vec3f(0, 0, 0);
  cv::Mat out;
  tone_map(frame, ToneCurve(1.0, kDefaults), out);
  const cv::Vec3f p = out.at<cv::Vec3f>(0, 0);
  EXPECT_NEAR(p[0] / p[1], 2.0f, 1e-5f);
  EXPECT_NEAR(p[2] / p[1], 0.5f, 1e-5f);
  EXPECT_EQ(out.at<cv::Vec3f>(0, 1), cv::Vec3f(0, 0, 0));
  EXPECT_EQ(out.at<cv::Vec3f>(0, 2), cv::Vec3f(0, 0, 0));
}

}  // namespace
}  // namespace eyestream::retina
