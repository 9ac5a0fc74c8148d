// Interrupts (pipeline/run/interrupts.hpp): a run stopped by SIGINT or SIGTERM
// keeps what it made, playable and complete, leaves no temporary, exits
// 128 + the signal, and a checkpointed run resumes from where it stopped
// to the bytes of an uninterrupted run. The signals are real (raised in
// the program after a chosen frame, through EYESTREAM_TEST_SIGNAL_AT_FRAME).
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "io/source_factory.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

namespace fs = std::filesystem;

// Sets an environment variable for the commands run while it lives.
struct ScopedEnv {
  ScopedEnv(const char* name, const std::string& value) : name_(name) { ::setenv(name, value.c_str(), 1); }
  ~ScopedEnv() { ::unsetenv(name_); }
  const char* name_;
};

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

class Interrupts : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(test::run_eyestream("sample night-drive -o " + (dir / "nd") + " --width 96 --height 54 --duration 1")
                  .exit_code,
              0);
  }
  std::string input() const { return "run -i " + (dir / "nd/frames") + " -g " + (dir / "nd/gaze.csv"); }
  test::ScratchDir dir;
};

TEST_F(Interrupts, CtrlCKeepsAPlayableVideoOfTheFramesSoFarAndItsReport) {
  fs::create_directories(dir.path() / "out");
  const ScopedEnv at("EYESTREAM_TEST_SIGNAL_AT_FRAME", "9");  // SIGINT after frame 9
  const auto r = test::run_eyestream(input() + " -o " + (dir / "out/v.mp4") + " --report " + (dir / "out/r.csv"));
  EXPECT_EQ(r.exit_code, 128 + SIGINT) << r.output;
  EXPECT_NE(r.output.find("interrupted by SIGINT; kept the first 10 frames"), std::string::npos) << r.output;
  EXPECT_EQ(names_in(dir.path() / "out"), (std::set<std::string>{"v.mp4", "r.csv", "r.json", "r.png"}))
      << "the outputs, and no temporary";
  // Playable: a reader finds its index and decodes all ten frames.
  io::SourceOptions sdr;
  sdr.video.transfer = "sdr";
  const auto video = io::open_source(dir / "out/v.mp4", sdr);
  int frames = 0;
  while (video->next()) ++frames;
  EXPECT_EQ(frames, 10);
  const std::string csv = test::read_bytes(dir / "out/r.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 10) << "a header and one row a frame";
}

TEST_F(Interrupts, SigtermWritesACheckpointThatResumesToTheUninterruptedBytes) {
  auto r = test::run_eyestream(input() + " -o " + (dir / "full/%05d.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string part = input() + " -o " + (dir / "part/%05d.png") + " --checkpoint " + (dir / "c.ckp");
  {
    const ScopedEnv at("EYESTREAM_TEST_SIGNAL_AT_FRAME", "4," + std::to_string(SIGTERM));
    r = test::run_eyestream(part);
  }
  EXPECT_EQ(r.exit_code, 128 + SIGTERM) << r.output;
  EXPECT_EQ(test::count_entries(dir.path() / "part"), 5) << "frames 0-4 kept, no temporary";
  EXPECT_NE(r.output.find("checkpoint " + (dir / "c.ckp") + " resumes at the next frame (--resume)"),
            std::string::npos)
      << r.output;
  r = test::run_eyestream(part + " --resume");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_EQ(test::count_entries(dir.path() / "part"), 30);
  EXPECT_EQ(test::first_differing_png(dir.path() / "full", dir.path() / "part", 30), "");
}

TEST_F(Interrupts, BeforeTheFirstWrittenFrameNothingIsKept) {
  fs::create_directories(dir.path() / "out");
  const ScopedEnv at("EYESTREAM_TEST_SIGNAL_AT_FRAME", "2");  // during the pre-roll before --start-frame 10
  const auto r = test::run_eyestream(input() + " -o " + (dir / "out/v.mp4") + " --start-frame 10 --preroll 1");
  EXPECT_EQ(r.exit_code, 128 + SIGINT) << r.output;
  EXPECT_NE(r.output.find("eyestream: error: interrupted by SIGINT before any frame was written; nothing kept"),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(names_in(dir.path() / "out").empty());
}

// `eyestream run -o - | head`: the reader goes away; one line says so
// (not "disk full"), the exit is 4 (output), and nothing is left behind.
TEST_F(Interrupts, AReaderClosingStandardOutputIsOneLineAndExitFour) {
  const std::string log = dir / "err.txt";
  const std::string command = "bash -c '" + std::string(EYESTREAM_BINARY) + " " + input() + " -o - 2>" + log +
                              " | head -c 100 >/dev/null; exit ${PIPESTATUS[0]}'";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 4);
  const std::string err = test::read_bytes(log);
  EXPECT_NE(err.find("eyestream: error: standard output: the program reading it closed the pipe ("),
            std::string::npos)
      << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}

}  // namespace
}  // namespace eyestream
