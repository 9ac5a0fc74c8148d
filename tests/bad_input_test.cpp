// One case per class of bad input through the command line: the exit code,
// a message naming the culprit, and nothing left at the output path.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "io/exr_file.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

namespace fs = std::filesystem;

struct BadCase {
  const char* name;
  int exit_code;
  const char* message;  // a part of the error line
};

class BadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    for (int k = 0; k < 3; ++k) write_frame(k, test::constant_frame(16, 12, {5, 5, 5}));
    std::ofstream(dir_ / "gaze.csv") << "t,x,y\n0,8,6\n0.05,9,6\n";
  }
  void write_frame(int k, const cv::Mat& rgb) {
    io::write_exr(dir_ / ("f_" + std::to_string(k) + ".exr"), rgb, {false, std::nullopt, 30.0});
  }
  // Runs on DIR/f_%d.exr and checks the outcome.
  void expect(const BadCase& c, const std::string& options = "") {
    const auto r = test::run_eyestream("run -i " + (dir_ / "f_%d.exr") + " -g " + (dir_ / "gaze.csv") + " -o " +
                                       (dir_ / "out.mp4") + " " + options);
    EXPECT_EQ(r.exit_code, c.exit_code) << c.name << ": " << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.name << ": " << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "out.mp4")) << c.name;
    int partials = 0;
    for (const auto& e : fs::directory_iterator(dir_.path()))
      partials += e.path().filename().string().find(".partial-") != std::string::npos;
    EXPECT_EQ(partials, 0) << c.name << ": temporary files removed";
  }
  test::ScratchDir dir_;
};

TEST_F(BadInput, TruncatedFrame) {
  const std::string bytes = test::read_bytes(dir_ / "f_1.exr");
  std::ofstream(dir_ / "f_1.exr", std::ios::binary | std::ios::trunc).write(bytes.data(), 200);
  expect({"truncated EXR", 3, "f_1.exr"});
}

TEST_F(BadInput, AbsurdDimensionsAreRefusedBeforeAllocating) {
  expect({"over --max-pixels", 3, "--max-pixels"}, "--max-pixels 100");
}

TEST_F(BadInput, FrameChangesSize) {
  write_frame(2, test::constant_frame(18, 12, {5, 5, 5}));
  expect({"size change", 3, "f_2.exr: frame 2 is 18x12"});
}

TEST_F(BadInput, MissingFrame) {
  fs::remove(dir_ / "f_1.exr");
  expect({"missing frame", 3, "f_1.exr"});
}

TEST_F(BadInput, NonFinitePixelsWithTheFailPolicy) {
  cv::Mat bad = test::constant_frame(16, 12, {5, 5, 5});
  bad.at<cv::Vec3f>(3, 3)[1] = std::numeric_limits<float>::quiet_NaN();
  write_frame(1, bad);
  expect({"NaN pixel", 3, "f_1.exr: frame 1 has 1 NaN"}, "--bad-pixels fail");
}

TEST_F(BadInput, GazeGoingBackwards) {
  std::ofstream(dir_ / "gaze.csv") << "t,x,y\n0,8,6\n0.05,9,6\n0.02,9,6\n";
  expect({"gaze backwards", 3, "gaze.csv:4"});
}

TEST_F(BadInput, GazeWithADuplicateTime) {
  std::ofstream(dir_ / "gaze.csv") << "t,x,y\n0,8,6\n0.05,9,6\n0.05,10,6\n";
  expect({"gaze duplicate", 3, "gaze.csv:4"});
}

TEST_F(BadInput, OutOfRangeOption) {
  expect({"out-of-range value", 2, "--viewer-age"}, "--viewer-age 250");
}

TEST_F(BadInput, UnknownOption) { expect({"unknown option", 2, "--viewr-age"}, "--viewr-age 25"); }

// A command-line error is one line like every other refusal.
TEST_F(BadInput, ACommandLineErrorIsOneErrorLine) {
  for (const std::string& args : {"run -i " + (dir_ / "f_%d.exr") + " -o " + (dir_ / "out.mp4") + " --viewr-age 25",
                                 std::string("run -i x.exr"), std::string("--frobnicate")}) {
    const auto r = test::run_eyestream(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(r.output.rfind("eyestream: error: ", 0), 0u) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
}

// Looking off the frame is allowed: the eye sees the surround there.
TEST_F(BadInput, GazeOutsideTheFrameSeesTheSurround) {
  std::ofstream(dir_ / "gaze.csv") << "t,x,y\n0,-500,6\n";
  const auto r = test::run_eyestream("run -i " + (dir_ / "f_%d.exr") + " -g " + (dir_ / "gaze.csv") + " -o " +
                                     (dir_ / "out.mp4") + " --surround 0.01 --report " + (dir_ / "r.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream csv(dir_ / "r.csv");
  std::string header, row;
  std::getline(csv, header), std::getline(csv, row);
  EXPECT_NE(row.find(",0.01,"), std::string::npos) << "adapted to the 0.01 cd/m^2 surround: " << row;
}

}  // namespace
}  // namespace eyestream
