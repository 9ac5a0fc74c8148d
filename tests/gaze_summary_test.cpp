// The gaze log against the video (io/gaze_summary.hpp): the summary line a
// run prints, --print-plan shows (refusing a log `run` would refuse) and the
// report's JSON keeps, and the warnings for a log mostly off the frame, one
// that misses the video's time span, and an implausible sample interval.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/test_support.hpp"

namespace eyestream {
namespace {

class GazeSummaryCli : public ::testing::Test {
 protected:
  void SetUp() override {  // 64x36, 1 s at 30 frames/s
    ASSERT_EQ(test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 64 --height 36 --duration 1")
                  .exit_code,
              0);
  }
  test::CommandResult run_with(const std::string& log, const std::string& extra = "") {
    std::ofstream(dir / "g.csv") << log;
    return test::run_eyestream("run -i " + (dir / "h/frames") + " -g " + (dir / "g.csv") + " -o " + (dir / "v.mp4") +
                               extra);
  }
  test::ScratchDir dir;
};

// Samples every `step` s from t0 to t1 at (x, y).
std::string log_of(double t0, double t1, double step, double x, double y) {
  std::string text = "t,x,y\n";
  for (double t = t0; t <= t1 + 1e-9; t += step)
    text += std::to_string(t) + "," + std::to_string(x) + "," + std::to_string(y) + "\n";
  return text;
}

TEST_F(GazeSummaryCli, APlausibleLogIsSummarisedWithoutWarnings) {
  const auto r = run_with(log_of(0, 1, 0.01, 32, 18), " --report " + (dir / "r.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("gaze: native, 101 samples at 100 Hz, 0.000 to 1.000 s, 0.0% lost, 0.0% closed, 0.0% off"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
  EXPECT_NE(test::read_bytes(dir / "r.json").find("\"samples\": 101"), std::string::npos);
}

TEST_F(GazeSummaryCli, OffFrameNonOverlappingAndImplausibleLogsAreWarnedAbout) {
  auto r = run_with(log_of(0, 1, 0.01, 640, 360));  // normalised-looking units taken as pixels of a bigger frame
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning: 100% of the open-eye gaze samples during the video fall off the 64x36 frame"), std::string::npos)
      << r.output;
  // Off the frame during the 1 s video, on it for the 9 s after: the video's share counts.
  r = run_with(log_of(0, 1, 0.01, 640, 360) + log_of(1.005, 10, 0.01, 32, 18).substr(6));
  EXPECT_NE(r.output.find("warning: 100% of the open-eye gaze samples during the video fall off"), std::string::npos)
      << r.output;
  r = run_with("t,x,y\n");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("g.csv: no gaze samples"), std::string::npos) << r.output;
  r = run_with(log_of(50, 51, 0.01, 32, 18));
  EXPECT_NE(r.output.find("warning: the gaze log (50.000 to 51.000 s) does not overlap the video (0 to 1.000 s)"),
            std::string::npos)
      << r.output;
  r = run_with(log_of(0, 1, 0.0001, 32, 18));  // microseconds read as seconds would look like this
  EXPECT_NE(r.output.find("warning: the median interval between gaze samples is 0.0001 s"), std::string::npos)
      << r.output;
}

TEST_F(GazeSummaryCli, PrintPlanShowsTheSummaryAndRefusesWhatRunRefuses) {
  auto r = run_with(log_of(0, 1, 0.01, 32, 18), " --print-plan");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("gaze: native, 101 samples"), std::string::npos) << r.output;
  r = run_with("t,x,y\n0,1,1\nzero,2,2\n", " --print-plan");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("g.csv"), std::string::npos) << r.output;
  // What run refuses before any work, --print-plan refuses too.
  r = run_with(log_of(0, 1, 0.01, 32, 18), " --print-plan --checkpoint " + (dir / "c.ckp") + " --checkpoint-every 5");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  std::ofstream(dir / "v.mp4") << "x";
  r = run_with(log_of(0, 1, 0.01, 32, 18), " --print-plan");
  EXPECT_EQ(r.exit_code, 4) << r.output;
}

}  // namespace
}  // namespace eyestream
