// The preview: viewers side by side, the plain tone-curve panel, and the
// burned-in gaze marker, labels and timecode.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgproc.hpp>

#include "io/exr_file.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

constexpr int kW = 160, kH = 90;

class Preview : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir();
    // 1 s of the night drive: the blink is at 0.833-0.983 s (frames 25-29).
    const auto r = test::run_eyestream("sample night-drive -o " + (*dir_ / "nd") + " --width 160 --height 90 " +
                                       "--duration 1");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  static void TearDownTestSuite() { delete dir_; }

  // Runs on the scene into DIR/name/%05d.exr (float, display-linear).
  static void run(const std::string& name, const std::string& options) {
    const auto r = test::run_eyestream("run -i " + (*dir_ / "nd/frames") + " -g " + (*dir_ / "nd/gaze.csv") +
                                       " -o " + (*dir_ / (name + "/%05d.exr")) + " " + options);
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  static cv::Mat frame(const std::string& name, int index) {
    char file[32];
    std::snprintf(file, sizeof(file), "/%05d.exr", index);
    return io::read_exr(*dir_ / (name + file), 1 << 22).rgb;
  }
  static double max_difference(const cv::Mat& a, const cv::Mat& b) {
    double m;
    const cv::Mat d = cv::abs(a - b);
    cv::minMaxLoc(d.reshape(1), nullptr, &m);
    return m;
  }
  // Below the label band at the top (labels are burned into each panel).
  static cv::Mat below_labels(const cv::Mat& panel) { return panel.rowRange(30, panel.rows); }

  static test::ScratchDir* dir_;
};
test::ScratchDir* Preview::dir_ = nullptr;

// Each viewer panel is that viewer's own simulation: the right panel of
// --viewers 25,75 equals a run with --viewer-age 75, pixel for pixel,
// outside the label.
TEST_F(Preview, ViewersSideBySideAreEachViewersOwnRun) {
  run("pair", "--viewers 25,75");
  run("old", "--viewer-age 75");
  run("young", "--viewer-age 25");
  for (int i : {0, 12, 29}) {
    const cv::Mat pair = frame("pair", i);
    ASSERT_EQ(pair.size(), cv::Size(2 * kW, kH));
    EXPECT_EQ(max_difference(below_labels(pair.colRange(kW, 2 * kW)), below_labels(frame("old", i))), 0.0) << i;
    EXPECT_EQ(max_difference(below_labels(pair.colRange(0, kW)), below_labels(frame("young", i))), 0.0) << i;
  }
  EXPECT_GT(max_difference(frame("old", 12), frame("young", 12)), 0.01) << "the viewers must differ";
  EXPECT_GT(max_difference(frame("pair", 12)(cv::Rect(0, 0, kW, 30)), frame("young", 12).rowRange(0, 30)), 0.5)
      << "labels burned in";
}

// --side-by-side puts the input through the plain tone curve (no glare,
// afterimages or mesopic effects) on the left.
TEST_F(Preview, SideBySideShowsThePlainToneCurveOnTheLeft) {
  run("sbs", "--side-by-side");
  run("plain", "--no-glare --no-mesopic --no-bleaching-afterimages --no-adaptation-afterimages");
  run("sim", "");
  const cv::Mat sbs = frame("sbs", 20);
  ASSERT_EQ(sbs.size(), cv::Size(2 * kW, kH));
  EXPECT_EQ(max_difference(below_labels(sbs.colRange(0, kW)), below_labels(frame("plain", 20))), 0.0);
  EXPECT_EQ(max_difference(below_labels(sbs.colRange(kW, 2 * kW)), below_labels(frame("sim", 20))), 0.0);
}

// The gaze marker is drawn around the gaze while the eyes are open and
// nowhere during a blink; the timecode only touches the bottom band.
TEST_F(Preview, GazeMarkerShowsOnlyWithOpenEyesAndTimecodeStaysInItsBand) {
  run("plainrun", "");
  run("marked", "--gaze-overlay --timecode");
  const cv::Mat open_diff = cv::abs(frame("marked", 10) - frame("plainrun", 10));
  const cv::Mat closed_diff = cv::abs(frame("marked", 27) - frame("plainrun", 27));
  // Road 40 m ahead: the gaze is near the frame centre, below the horizon.
  cv::Mat changed;
  cv::cvtColor(open_diff, changed, cv::COLOR_RGB2GRAY);
  const cv::Rect marker_zone(0, 0, kW, kH - 20);
  EXPECT_GT(cv::countNonZero(changed(marker_zone) > 0.01), 20) << "a marker while the eyes are open";
  cv::cvtColor(closed_diff, changed, cv::COLOR_RGB2GRAY);
  EXPECT_EQ(cv::countNonZero(changed(marker_zone) > 0), 0) << "no marker and nothing else during the blink";
  EXPECT_GT(cv::countNonZero(changed.rowRange(kH - 20, kH) > 0.01), 20) << "the timecode";
}

TEST_F(Preview, ViewerFilesCarryALabelAndBadViewersAreUsageErrors) {
  {
    std::ofstream(*dir_ / "older.json") << R"({"label": "older driver", "viewer-age": 75})";
    std::ofstream(*dir_ / "typo.json") << R"({"viewer-agee": 75})";
  }
  const std::string base = "run -i " + (*dir_ / "nd/frames") + " --viewers ";
  const auto ok = test::run_eyestream(base + "30," + (*dir_ / "older.json") + " -o " + (*dir_ / "v/%05d.png") +
                                      " --report " + (*dir_ / "v.csv"));
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  std::ifstream csv(*dir_ / "v.csv");
  std::string header, first, second;
  std::getline(csv, header), std::getline(csv, first), std::getline(csv, second);
  EXPECT_NE(first.find(",age 30,"), std::string::npos) << first;
  EXPECT_NE(second.find(",older driver,"), std::string::npos) << second;
  for (const std::string& bad : {std::string("25,0"), std::string("25,,70"), *dir_ / "typo.json", *dir_ / "none.json"}) {
    const auto r = test::run_eyestream(base + bad + " -o " + (*dir_ / "bad/%05d.png"));
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
    EXPECT_EQ(test::count_entries(dir_->path() / "bad"), 0);
  }
  const auto typo = test::run_eyestream(base + (*dir_ / "typo.json") + " -o " + (*dir_ / "bad/%05d.png"));
  EXPECT_NE(typo.output.find("typo.json"), std::string::npos) << typo.output;
  EXPECT_NE(typo.output.find("viewer-agee"), std::string::npos) << typo.output;
}

}  // namespace
}  // namespace eyestream
