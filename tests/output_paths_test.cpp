// Every output of a run is resolved before the first frame: two that would
// be the same file, or one that would replace an input, are refused with
// nothing written.
#include <gtest/gtest.h>

#include <fstream>

#include "io/exr_file.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

namespace fs = std::filesystem;

class OutputPaths : public ::testing::Test {
 protected:
  void SetUp() override {
    for (int k = 0; k < 3; ++k)
      io::write_exr(dir_ / ("f_" + std::to_string(k) + ".exr"), test::constant_frame(16, 12, {5, 5, 5}),
                    {false, std::nullopt, 30.0});
    std::ofstream(dir_ / "gaze.csv") << "t,x,y\n0,8,6\n";
  }
  test::CommandResult run(const std::string& outputs) {
    return test::run_eyestream("run -i " + (dir_ / "f_%d.exr") + " -g " + (dir_ / "gaze.csv") + " " + outputs);
  }
  // Files in the folder besides the inputs.
  int written() const { return test::count_entries(dir_.path()) - 4; }
  test::ScratchDir dir_;
};

TEST_F(OutputPaths, TwoOutputsThatAreOneFileAreRefusedBeforeAnythingIsWritten) {
  const std::string v = " -o " + (dir_ / "v.mp4");
  const struct {
    std::string options, message;
  } cases[] = {
      {v + " --report " + (dir_ / "r.csv") + " --state-exr " + (dir_ / "r.png"), "--state-exr (" + (dir_ / "r.png")},
      {" -o " + (dir_ / "frames/%05d.png") + " --report " + (dir_ / "frames/00002.csv"), "--report's chart"},
      {v + " --report " + (dir_ / "r.json"), "--report's JSON summary"},
      {v + " --state-exr " + (dir_ / "v.mp4"), "would write the same file as -o"},
  };
  for (const auto& c : cases) {
    const auto r = run(c.options);
    EXPECT_EQ(r.exit_code, 2) << c.options << ": " << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
    EXPECT_EQ(written(), 0) << c.options;
  }
}

TEST_F(OutputPaths, AnOutputThatWouldReplaceAnInputIsRefusedFirst) {
  const auto r = run("-o " + (dir_ / "v.mp4") + " --report " + (dir_ / "gaze.csv"));
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("gaze.csv: output would overwrite an input file"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "v.mp4")) << "refused before the video was written";
  EXPECT_EQ(test::read_bytes(dir_ / "gaze.csv"), "t,x,y\n0,8,6\n");
}

TEST_F(OutputPaths, EveryOutputAppearsWhenTheRunSucceeds) {
  const auto r = run("-o " + (dir_ / "v.mp4") + " --report " + (dir_ / "r.csv") + " --state-exr " + (dir_ / "s.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"v.mp4", "r.csv", "r.json", "r.png", "s.exr"}) EXPECT_TRUE(fs::exists(dir_ / f)) << f;
  EXPECT_EQ(written(), 5) << "no temporaries left";
}

}  // namespace
}  // namespace eyestream
