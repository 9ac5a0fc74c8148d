#include "pipeline/eye/gaze_timeline.hpp"

#include <gtest/gtest.h>

namespace eyestream::pipeline {
namespace {

using io::EyeState;

TEST(GazeTimeline, WithoutSamplesTheGazeStaysAtTheCentre) {
  GazeTimeline t({}, 50, 40);
  const auto s = t.segments(0.0, 0.1);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_DOUBLE_EQ(s[0].x, 50);
  EXPECT_DOUBLE_EQ(s[0].duration(), 0.1);
}

TEST(GazeTimeline, IntervalsAreCutAtSampleTimes) {
  GazeTimeline t({{0.0, 1, 1, EyeState::kOpen}, {0.02, 2, 2, EyeState::kOpen}, {0.05, 3, 3, EyeState::kOpen}}, 0, 0);
  const auto s = t.segments(0.01, 0.06);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_DOUBLE_EQ(s[0].x, 1);
  EXPECT_NEAR(s[0].duration(), 0.01, 1e-12);
  EXPECT_DOUBLE_EQ(s[1].x, 2);
  EXPECT_NEAR(s[1].duration(), 0.03, 1e-12);
  EXPECT_DOUBLE_EQ(s[2].x, 3);
  EXPECT_NEAR(s[2].t1_s, 0.06, 1e-12);
}

TEST(GazeTimeline, BlinksCloseTheEyeAndLostSamplesHoldTheLastPosition) {
  GazeTimeline t({{0.0, 10, 10, EyeState::kOpen},
                  {0.1, 0, 0, EyeState::kClosed},
                  {0.2, 0, 0, EyeState::kLost},
                  {0.3, 20, 20, EyeState::kOpen}},
                 0, 0);
  const auto s = t.segments(0.0, 0.4);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_FALSE(s[0].eye_closed);
  EXPECT_TRUE(s[1].eye_closed);
  EXPECT_DOUBLE_EQ(s[1].x, 10);
  EXPECT_FALSE(s[2].eye_closed);
  EXPECT_DOUBLE_EQ(s[2].x, 10);
  EXPECT_DOUBLE_EQ(s[3].x, 20);
}

TEST(GazeTimeline, BeforeTheFirstSampleItHoldsAndAfterTheLastItHolds) {
  GazeTimeline t({{1.0, 7, 8, EyeState::kOpen}}, 0, 0);
  EXPECT_DOUBLE_EQ(t.segments(0.0, 0.5)[0].x, 7);
  EXPECT_DOUBLE_EQ(t.segments(5.0, 6.0)[0].y, 8);
}

TEST(GazeTimeline, EmptyIntervalGivesOneZeroLengthSegment) {
  GazeTimeline t({{0.0, 1, 1, EyeState::kOpen}}, 0, 0);
  const auto s = t.segments(2.0, 2.0);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].duration(), 0.0);
}

}  // namespace
}  // namespace eyestream::pipeline
