#include "io/gaze_csv.hpp"

#include <gtest/gtest.h>

#include "io/error.hpp"
#include "io/gaze_import.hpp"
#include "tests/test_support.hpp"

namespace eyestream::io {
namespace {

std::vector<GazeSample> parse(const std::string& text, GazeUnits units = GazeUnits::kPixels) {
  return parse_gaze_csv(text, "gaze.csv", units, 200, 100);
}

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GazeCsv, ParsesSamplesEventsAndBlinksWithoutPositions) {
  const auto s = parse("t,x,y,event\n0,10,20,fixation\n0.5,11,21,saccade\n0.6,,,blink\n0.8,,,lost\n1.0,30,40,\n");
  ASSERT_EQ(s.size(), 5u);
  EXPECT_EQ(s[0].state, EyeState::kOpen);
  EXPECT_EQ(s[1].state, EyeState::kOpen);
  EXPECT_EQ(s[2].state, EyeState::kClosed);
  EXPECT_EQ(s[3].state, EyeState::kLost);
  EXPECT_DOUBLE_EQ(s[4].x, 30.0);
  EXPECT_DOUBLE_EQ(s[4].t_s, 1.0);
}

TEST(GazeCsv, EventColumnIsOptionalAndColumnsMayBeReordered) {
  const auto s = parse("y,t,x\n5,0.1,7\n");
  ASSERT_EQ(s.size(), 1u);
  EXPECT_DOUBLE_EQ(s[0].x, 7.0);
  EXPECT_DOUBLE_EQ(s[0].y, 5.0);
}

TEST(GazeCsv, NormalisedUnitsScaleToFramePixels) {
  const auto s = parse("t,x,y\n0,0.5,0.25\n", GazeUnits::kNormalised);
  EXPECT_DOUBLE_EQ(s[0].x, 100.0);
  EXPECT_DOUBLE_EQ(s[0].y, 25.0);
}

TEST(GazeCsv, GapsBetweenSamplesAreAccepted) {
  const auto s = parse("t,x,y\n0,1,1\n5.0,2,2\n");
  EXPECT_EQ(s.size(), 2u);
}

TEST(GazeCsv, MalformedLinesNameTheirLineNumber) {
  EXPECT_NE(error_of("t,x,y\n0,1,1\n0.1,abc,2\n").find("gaze.csv:3"), std::string::npos);
  EXPECT_NE(error_of("t,x,y\n0,1\n").find("gaze.csv:2"), std::string::npos);
  EXPECT_NE(error_of("t,x,y,event\n0,1,1,wink\n").find("gaze.csv:2"), std::string::npos);
  EXPECT_NE(error_of("t,x,y\n0,1,1\n0,2,2\n").find("gaze.csv:3"), std::string::npos);    // duplicate time
  EXPECT_NE(error_of("t,x,y\n1,1,1\n0.5,2,2\n").find("gaze.csv:3"), std::string::npos);  // backwards
  EXPECT_NE(error_of("time,x,y\n0,1,1\n").find("gaze.csv:1"), std::string::npos);
  EXPECT_NE(error_of("t,x,y\nnan,1,1\n").find("gaze.csv:2"), std::string::npos);
  EXPECT_NE(error_of("").find("empty"), std::string::npos);
}

TEST(GazeCsv, WriteThenReadRoundTrips) {
  test::ScratchDir dir;
  std::vector<GazeSample> in = {
      {0.0, 1.5, 2.5, EyeState::kOpen}, {0.1, 3, 4, EyeState::kClosed}, {0.2, 5, 6, EyeState::kLost}};
  write_gaze_csv(dir / "g.csv", in);
  GazeImportOptions o;
  o.frame_width = o.frame_height = 10;
  const auto out = read_gaze(dir / "g.csv", o);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_DOUBLE_EQ(out[0].x, 1.5);
  EXPECT_EQ(out[1].state, EyeState::kClosed);
  EXPECT_EQ(out[2].state, EyeState::kLost);
}

}  // namespace
}  // namespace eyestream::io
