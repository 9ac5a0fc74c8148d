// Checkpoint and resume: a run killed after a checkpoint, resumed with the
// same command, ends with the same output and report bytes as a run that
// was never interrupted; a checkpoint from other settings is refused.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "tests/test_support.hpp"

namespace eyestream {
namespace {

namespace fs = std::filesystem;

TEST(Checkpoint, ResumeAfterAKillGivesTheUninterruptedBytes) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample night-drive -o " + (dir / "nd") + " --width 96 --height 54 --duration 1")
                .exit_code,
            0);
  const std::string in = "run -i " + (dir / "nd/frames") + " -g " + (dir / "nd/gaze.csv") + " --viewers 25,75";
  auto r = test::run_eyestream(in + " -o " + (dir / "full/%05d.png") + " --report " + (dir / "full.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string part = in + " -o " + (dir / "part/%05d.png") + " --report " + (dir / "part.csv") +
                           " --checkpoint " + (dir / "state.ckp");
  // Killed (no clean-up at all) after frame 17; the last checkpoint is after frame 14.
  const std::string killed = "EYESTREAM_TEST_KILL_AT_FRAME=17 " + std::string(EYESTREAM_BINARY) + " " + part +
                             " --checkpoint-every 5 > /dev/null 2>&1";
  EXPECT_NE(std::system(killed.c_str()), 0) << "the run was killed";
  ASSERT_TRUE(fs::exists(dir / "state.ckp"));
  EXPECT_EQ(test::count_entries(dir.path() / "part"), 15 + 3) << "frames 0-14 kept, 15-17 left as temporaries";
  r = test::run_eyestream(part + " --resume");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::count_entries(dir.path() / "part"), 30) << "every frame, no temporaries left";
  for (int k = 0; k < 30; ++k) {
    char name[16];
    std::snprintf(name, sizeof(name), "%05d.png", k);
    EXPECT_TRUE(test::read_bytes(dir / (std::string("full/") + name)) ==
                test::read_bytes(dir / (std::string("part/") + name)))
        << name;
  }
  EXPECT_EQ(test::read_bytes(dir / "full.csv"), test::read_bytes(dir / "part.csv"));
  EXPECT_EQ(test::read_bytes(dir / "full.json"), test::read_bytes(dir / "part.json"));
  // Other settings: refused, naming the checkpoint.
  r = test::run_eyestream(part + " --resume --viewer-age 60");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("state.ckp: written by a run with other settings"), std::string::npos) << r.output;
  // Videos cannot be checkpointed: say so.
  r = test::run_eyestream(in + " -o " + (dir / "v.mp4") + " --checkpoint " + (dir / "v.ckp") + " --checkpoint-every 5");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("eyestream chunks"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace eyestream
