// Charts of the report: parsing, what they mark, and the `report` command.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "io/error.hpp"
#include "pipeline/report/report_charts.hpp"
#include "pipeline/report/report_writer.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

using pipeline::parse_report;

// A report of `frames` frames for viewers "a" and "b"; frames from
// `closed_from` on have the eyes closed; with a target when `target`.
std::string report_text(int frames, int closed_from, bool target) {
  std::string text = std::string(pipeline::kReportColumns) + "\n";
  for (int i = 0; i < frames; ++i)
    for (const char* v : {"a", "b"}) {
      const bool closed = i >= closed_from;
      text += std::to_string(i) + "," + std::to_string(i / 30.0) + "," + v + ",1,2," + (closed ? "closed" : "open") +
              ",0.5,4.1,1e5,1," + (closed ? "," : "0.2,30") + ",1," +
              (target ? "0.6,0.3,0.2,1,0.6" : ",,,,") + ",1,1,0,0,4.1,\n";
    }
  return text;
}

int pixels_of_colour(const cv::Mat& img, cv::Vec3b bgr, int from_row) {
  int n = 0;
  for (int y = from_row; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) n += img.at<cv::Vec3b>(y, x) == bgr;
  return n;
}

TEST(ReportCharts, ParsesOneSeriesPerViewerWithEmptyFieldsAsNaN) {
  const auto series = parse_report(report_text(10, 8, false), "r.csv");
  ASSERT_EQ(series.size(), 2u);
  EXPECT_EQ(series[1].label, "b");
  ASSERT_EQ(series[0].time_s.size(), 10u);
  EXPECT_DOUBLE_EQ(series[0].pupil_mm[3], 4.1);
  EXPECT_TRUE(std::isnan(series[0].veil_cd_m2[9])) << "empty veil during the blink";
  EXPECT_TRUE(series[0].eye_closed[9]);
  EXPECT_FALSE(series[0].eye_closed[7]);
}

TEST(ReportCharts, MalformedReportsNameTheFileAndLine) {
  std::string text = report_text(3, 3, false);
  try {
    parse_report("frame,time_s\n0,0\n", "x.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.csv"), std::string::npos) << e.what();
  }
  text.replace(text.find("4.1"), 3, "lots");  // the first row's pupil
  try {
    parse_report(text, "y.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("y.csv:2"), std::string::npos) << e.what();
  }
}

TEST(ReportCharts, BlinksAreShadedAndATargetAddsItsContrastChart) {
  test::ScratchDir dir;
  pipeline::write_report_charts(parse_report(report_text(60, 40, true), "r"), dir / "blink.png");
  pipeline::write_report_charts(parse_report(report_text(60, 60, false), "r"), dir / "open.png");
  const cv::Mat blink = cv::imread(dir / "blink.png"), open = cv::imread(dir / "open.png");
  ASSERT_FALSE(blink.empty());
  ASSERT_FALSE(open.empty());
  const cv::Vec3b shade(215, 215, 215);
  // A third of each chart's width shaded, against a few antialiased text pixels of that grey.
  EXPECT_GT(pixels_of_colour(blink, shade, 40), 50000) << "the blink shaded below the legend";
  EXPECT_LT(pixels_of_colour(open, shade, 40), 1000);
  EXPECT_GT(blink.rows, open.rows) << "the contrast chart";
  EXPECT_GT(pixels_of_colour(open, cv::Vec3b(0, 140, 255), 40), 1000) << "glare activity marked";
}

TEST(ReportCharts, TheReportCommandDrawsAndRefusesBadFiles) {
  test::ScratchDir dir;
  std::ofstream(dir / "r.csv") << report_text(20, 15, true);
  std::ofstream(dir / "bad.csv") << "frame,time_s\n0,0\n";
  auto r = test::run_eyestream("report " + (dir / "r.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(cv::imread(dir / "r.png").empty());
  r = test::run_eyestream("report " + (dir / "bad.csv") + " -o " + (dir / "bad.png"));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("bad.csv"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
  const std::string before = test::read_bytes(dir / "r.csv");
  r = test::run_eyestream("report " + (dir / "r.csv") + " -o " + (dir / "r.csv"));
  EXPECT_EQ(r.exit_code, 2) << "refused: the report command writes PNG only; " << r.output;
  EXPECT_EQ(test::read_bytes(dir / "r.csv"), before) << "the input is never overwritten";
}

}  // namespace
}  // namespace eyestream
