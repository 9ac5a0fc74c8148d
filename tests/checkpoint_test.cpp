// Checkpoint and resume: a run killed after a checkpoint, resumed with the
// same command, ends with the same output and report bytes as a run that
// was never interrupted; a checkpoint from other settings is refused.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
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
  // Frames 0-14 kept under their names; 15-17 at most as temporaries (the
  // writer thread may not have reached them when the process died).
  EXPECT_TRUE(fs::exists(dir / "part/00014.png"));
  EXPECT_FALSE(fs::exists(dir / "part/00015.png"));
  EXPECT_GE(test::count_entries(dir.path() / "part"), 15);
  EXPECT_LE(test::count_entries(dir.path() / "part"), 15 + 3);
  r = test::run_eyestream(part + " --resume");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::count_entries(dir.path() / "part"), 30) << "every frame, no temporaries left";
  EXPECT_EQ(test::first_differing_png(dir.path() / "full", dir.path() / "part", 30), "");
  EXPECT_EQ(test::read_bytes(dir / "full.csv"), test::read_bytes(dir / "part.csv"));
  EXPECT_EQ(test::read_bytes(dir / "full.json"), test::read_bytes(dir / "part.json"));
  // Other settings: refused, naming the checkpoint and the setting.
  r = test::run_eyestream(part + " --resume --viewer-age 60");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("state.ckp: written by a run with other settings"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("viewer-age=25, this run has viewer-age=60"), std::string::npos) << r.output;
  // Videos cannot be checkpointed: say so.
  r = test::run_eyestream(in + " -o " + (dir / "v.mp4") + " --checkpoint " + (dir / "v.ckp") + " --checkpoint-every 5");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("eyestream chunks"), std::string::npos) << r.output;
}

// FNV-1a, 64 bits, as the checkpoint's checksum is defined (checkpoint.hpp).
std::uint64_t fnv1a(const std::string& bytes, size_t from) {
  std::uint64_t h = 1469598103934665603ULL;
  for (size_t i = from; i < bytes.size(); ++i) h = (h ^ static_cast<unsigned char>(bytes[i])) * 1099511628211ULL;
  return h;
}

std::uint64_t u64_at(const std::string& bytes, size_t at) {
  std::uint64_t v;
  std::memcpy(&v, bytes.data() + at, 8);
  return v;
}

void put_u64_at(std::string& bytes, size_t at, std::uint64_t v) { std::memcpy(bytes.data() + at, &v, 8); }

// A corrupt or malformed checkpoint is refused, exit 3, naming the file and
// what is wrong, before any state is touched (it could corrupt memory).
TEST(Checkpoint, CorruptAndMalformedCheckpointsAreRefusedNamingWhatIsWrong) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample night-drive -o " + (dir / "nd") + " --width 64 --height 36 --duration 0.5")
                .exit_code,
            0);
  const std::string cmd = "run -i " + (dir / "nd/frames") + " -g " + (dir / "nd/gaze.csv") + " -o " +
                          (dir / "out/%05d.png") + " --checkpoint " + (dir / "s.ckp");
  ASSERT_EQ(test::run_eyestream(cmd + " --checkpoint-every 5").exit_code, 0);
  const std::string good = test::read_bytes(dir / "s.ckp");
  const size_t magic = 23;  // "EYESTREAM-CHECKPOINT-2\n"
  ASSERT_EQ(good.substr(0, magic), "EYESTREAM-CHECKPOINT-2\n");
  ASSERT_EQ(u64_at(good, magic), fnv1a(good, magic + 8)) << "the checksum is FNV-1a of the rest";
  auto resume_with = [&](const std::string& bytes) {
    std::ofstream(dir / "s.ckp", std::ios::binary) << bytes;
    return test::run_eyestream(cmd + " --resume");
  };
  // One flipped byte in the state.
  std::string flipped = good;
  flipped[flipped.size() - 100] ^= 0x40;
  auto r = resume_with(flipped);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("s.ckp: checkpoint is corrupt"), std::string::npos) << r.output;
  // A calcium-deficit matrix with half the rows of the bleaching matrix,
  // checksum recomputed: the sizes are checked against the plan.
  const size_t json_at = magic + 16, json_length = u64_at(good, magic + 8);
  size_t at = json_at + json_length;  // the first matrix: type, rows, cols, data
  const std::uint64_t type = u64_at(good, at), rows = u64_at(good, at + 8), cols = u64_at(good, at + 16);
  const size_t element = (type % 8 == 6 ? 8 : 4) * (1 + type / 8), first = 24 + rows * cols * element;
  std::string shrunk = good;
  at += first;  // the second matrix
  put_u64_at(shrunk, at + 8, rows / 2);
  shrunk.erase(at + 24 + (rows / 2) * cols * element, (rows - rows / 2) * cols * element);
  put_u64_at(shrunk, magic, fnv1a(shrunk, magic + 8));
  r = resume_with(shrunk);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("s.ckp: not a valid checkpoint (panel 1: the calcium deficit matrix is"), std::string::npos)
      << r.output;
  // An absurd matrix count.
  std::string absurd = good;
  const size_t count_at = absurd.find("\"matrices\":6");
  ASSERT_NE(count_at, std::string::npos);
  absurd.replace(count_at, 12, "\"matrices\":1000000000000");
  put_u64_at(absurd, magic + 8, u64_at(absurd, magic + 8) + 12);
  put_u64_at(absurd, magic, fnv1a(absurd, magic + 8));
  r = resume_with(absurd);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("s.ckp: not a valid checkpoint (1000000000000 matrices)"), std::string::npos) << r.output;
  // Time skipped at rest of 1e300 s (found by the checkpoint fuzz target:
  // its catch-up blur overflowed OpenCV's kernel size).
  std::string forever = good;
  const size_t last = forever.size() - 24;  // the bookkeeping's three doubles end the file
  const double absurd_dt = 1e300;
  std::memcpy(&forever[last + 8], &absurd_dt, 8);
  put_u64_at(forever, magic, fnv1a(forever, magic + 8));
  r = resume_with(forever);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("the resting bookkeeping is out of range"), std::string::npos) << r.output;
  // The good one still resumes.
  r = resume_with(good);
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

}  // namespace
}  // namespace eyestream
