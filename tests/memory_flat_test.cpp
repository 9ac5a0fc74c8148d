// Memory does not grow with the length of a run, for every output kind:
// the peak resident memory of 100 000 frames is within 8 MiB of that of
// 1000 (small frames, so per-frame bookkeeping, not the frame, would show:
// the image sinks' old list of staged files grew 39 MB). An MP4 file's
// sample tables stay in memory until its index is written at the end
// (libavformat's mov muxer), some 20-40 bytes a frame: 1.7 to 4.0 MiB here
// over 100 000 frames. Not built with AddressSanitizer, whose quarantine keeps freed
// memory resident by design.
#include <gtest/gtest.h>

#if !defined(__SANITIZE_ADDRESS__)

#include <cstdio>
#include <fstream>
#include <string>

#include "tests/test_support.hpp"

namespace eyestream {
namespace {

// Peak resident memory (KiB) of one run over `frames` raw 16x16 frames.
long peak_kib(const test::ScratchDir& dir, long frames, const std::string& output) {
  const std::string command = "head -c " + std::to_string(16L * 16 * 12 * frames) +
                              " /dev/zero | /usr/bin/time -f %M -o " + (dir / "rss.txt") + " " EYESTREAM_BINARY +
                              " run -y -i - --size 16x16 -g " + (dir / "gaze.csv") + " --no-progress " + output +
                              " > /dev/null 2> " + (dir / "err.txt");
  if (std::system(command.c_str()) != 0) return -1;
  long kib = -1;
  std::ifstream(dir / "rss.txt") >> kib;
  return kib;
}

// The peak of 100 000 frames is within 8 MiB of that of 1000 for one kind
// of output. One test per kind, so that each has its own time limit: all
// five in one took 86-111 s here, and over ten minutes on one CI machine
// (sixteen-pixel frames spend their time handing work between threads).
// `target` is a name in the scratch folder, or "-" for standard output.
void expect_flat(const std::string& name, const std::string& target, const std::string& extra = "") {
  test::ScratchDir dir;
  std::ofstream(dir / "gaze.csv") << "t,x,y\n0,8,8\n";
  const std::string output = "-o " + (target == "-" ? target : dir / target) + extra;
  const long short_run = peak_kib(dir, 1000, output);
  ASSERT_GT(short_run, 0) << name << ": " << test::read_bytes(dir / "err.txt");
  std::filesystem::remove_all(dir / "frames");
  const long long_run = peak_kib(dir, 100000, output);
  ASSERT_GT(long_run, 0) << name << ": " << test::read_bytes(dir / "err.txt");
  EXPECT_LT(long_run - short_run, 8 * 1024)
      << name << ": " << short_run << " KiB after 1000 frames, " << long_run << " KiB after 100 000";
  std::printf("%s: %ld KiB after 1000 frames, %ld KiB after 100 000\n", name.c_str(), short_run, long_run);
}

TEST(MemoryFlat, APngSequenceDoesNotGrowOverALongRun) { expect_flat("PNG", "frames/%06d.png"); }

TEST(MemoryFlat, AnExrSequenceDoesNotGrowOverALongRun) { expect_flat("EXR", "frames/%06d.exr"); }

TEST(MemoryFlat, AnH264FileDoesNotGrowOverALongRun) { expect_flat("H.264", "v.mp4"); }

TEST(MemoryFlat, A10BitHevcFileDoesNotGrowOverALongRun) { expect_flat("HEVC 10-bit", "v.mkv", " --bit-depth 10"); }

TEST(MemoryFlat, H264OnStandardOutputDoesNotGrowOverALongRun) {
  expect_flat("H.264 on standard output", "-", " --format mp4");
}

}  // namespace
}  // namespace eyestream

#endif
