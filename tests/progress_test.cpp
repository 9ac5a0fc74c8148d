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
