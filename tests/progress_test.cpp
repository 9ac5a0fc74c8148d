// Messages of a run on a non-terminal stderr (CI, Slurm): plain progress
// lines at --progress-every, none with --quiet, which leaves nothing at
// all on success.
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/test_support.hpp"

namespace eyestream {
namespace {

TEST(Progress, PlainLinesOffATerminalAndSilenceWithQuiet) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 64 --height 36 --duration 0.5")
                .exit_code,
            0);
  const std::string in = "run -y -i " + (dir / "h/frames") + " -o " + (dir / "v.mp4");
  auto r = test::run_eyestream(in + " --progress-every 0");  // a line a frame
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("eyestream: 1/15 frames, "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("eyestream: 15/15 frames, "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\r'), std::string::npos) << "no bar drawing off a terminal";
  r = test::run_eyestream(in + " --progress-every 0 --quiet");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.output, "");
  r = test::run_eyestream(in);  // the default: every 10 s, so a short run prints its summary only
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

}  // namespace
}  // namespace eyestream

namespace eyestream {
namespace {

// For programs: --progress-file holds key=value blocks, the last one
// progress=end with every frame counted.
TEST(Progress, AProgressFileForPrograms) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 64 --height 36 --duration 0.5")
                .exit_code,
            0);
  const auto r = test::run_eyestream("run -i " + (dir / "h/frames") + " -o " + (dir / "v.mp4") + " --progress-file " +
                                     (dir / "p.txt"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string text = test::read_bytes(dir / "p.txt");
  const size_t last = text.rfind("frame=");
  ASSERT_NE(last, std::string::npos) << text;
  const std::string block = text.substr(last);
  EXPECT_EQ(block.rfind("frame=15\ntotal_frames=15\nfps=", 0), 0u) << block;
  EXPECT_NE(block.find("\nelapsed_s="), std::string::npos) << block;
  EXPECT_TRUE(block.size() > 13 && block.substr(block.size() - 13) == "progress=end\n") << block;
}

}  // namespace
}  // namespace eyestream
