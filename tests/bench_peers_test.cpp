// `eyestream bench --peers`: a peer not on PATH is skipped and said so; an
// installed one is run on the bench's own frames and its time read the way
// the table says (stand-in programs on PATH that record what they were
// given and take a known time).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <regex>

#include "tests/test_support.hpp"

namespace eyestream {
namespace {

const std::string kBench = "bench --scene night-city --sizes 64x36 --presets fast --frames 3 --no-skip-study --peers";

// PATH set to `path` while it lives.
struct PathSetting {
  explicit PathSetting(const std::string& path) : old_(std::getenv("PATH") ? std::getenv("PATH") : "") {
    ::setenv("PATH", path.c_str(), 1);
  }
  ~PathSetting() { ::setenv("PATH", old_.c_str(), 1); }
  std::string old_;
};

void write_program(const std::string& path, const std::string& body) {
  std::ofstream(path) << "#!/bin/sh\n" << body;
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
}

// The table's line for `peer`, or "".
std::string line_of(const std::string& output, const std::string& peer) {
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(peer, 0) == 0) return line;
  return "";
}

TEST(BenchPeers, APeerNotOnThePathIsSkippedAndSaidSo) {
  test::ScratchDir empty;
  const PathSetting path(empty.path().string());
  const test::CommandResult r = test::run_eyestream(kBench);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(line_of(r.output, "pfstmo_pattanaik00 -t").find("skipped: not installed"), std::string::npos) << r.output;
  EXPECT_NE(line_of(r.output, "blender fog glow").find("skipped: not installed"), std::string::npos) << r.output;
}

TEST(BenchPeers, InstalledPeersRunOnTheBenchFramesAndTheirTimesAreRead) {
  test::ScratchDir fakes;
  const std::string log = fakes / "args.txt";
  // pfsinexr: records its arguments and writes a stream; the operator
  // takes 0.6 s for the 3 frames (at least 200 ms a frame) and copies it.
  write_program(fakes / "pfsinexr", "echo \"pfsinexr $*\" >> " + log + "\n/bin/echo stream\n");
  write_program(fakes / "pfstmo_pattanaik00",
                "echo \"pfstmo $*\" >> " + log + "\n/bin/sleep 0.6\n/bin/cat\n");
  // blender: the first run (loading) slowest, the fastest after it 7.25 ms.
  write_program(fakes / "blender", "echo \"blender $*\" >> " + log +
                                       "\necho 'fog glow run 0: 3.000 ms'\necho 'fog glow run 1: 9.500 ms'\n"
                                       "echo 'fog glow run 2: 7.250 ms'\n");
  const PathSetting path(fakes.path().string());
  const test::CommandResult r = test::run_eyestream(kBench);
  ASSERT_EQ(r.exit_code, 0) << r.output;

  const std::string args = test::read_bytes(log);
  EXPECT_TRUE(std::regex_search(args, std::regex("pfsinexr \\S+/frames/%05d\\.exr --frames 0:2"))) << args;
  EXPECT_NE(args.find("pfstmo -t --fps 30"), std::string::npos) << args;
  EXPECT_TRUE(std::regex_search(args, std::regex("blender -b --factory-startup .*--python \\S+\\.py -- \\S+/frames/00001\\.exr 3")))
      << args;

  std::smatch m;
  const std::string pattanaik = line_of(r.output, "pfstmo_pattanaik00 -t");
  // peer_ms, io_ms ("-": no cat on this PATH), eyestream, ratio
  ASSERT_TRUE(std::regex_search(pattanaik, m, std::regex("64x36 +([0-9.]+) +- +([0-9.]+) +([0-9.]+)x +12x")))
      << r.output;
  const double peer = std::stod(m[1]), eye = std::stod(m[2]), ratio = std::stod(m[3]);
  EXPECT_GE(peer, 200.0) << pattanaik;
  EXPECT_LT(peer, 2000.0) << pattanaik;
  // The ratio is the unrounded times': within what rounding each to 0.1 allows.
  if (eye > 0.05) {
    EXPECT_GE(ratio + 0.05, (peer - 0.05) / (eye + 0.05)) << pattanaik;
    EXPECT_LE(ratio - 0.05, (peer + 0.05) / (eye - 0.05)) << pattanaik;
  }

  const std::string fog = line_of(r.output, "blender fog glow");
  ASSERT_TRUE(std::regex_search(fog, m, std::regex("64x36 +7\\.2 +- +([0-9.]+) +([0-9.]+)x +100x +([0-9.]+)%"))) << r.output;
  // fast's split engine against the exact engine on the same frame: their
  // totals differ by under 1 % of the light the exact engine moved.
  EXPECT_LT(std::stod(m[3]), 1.0) << fog;
}

TEST(BenchPeers, APeerThatFailsIsReportedNotFatal) {
  test::ScratchDir fakes;
  write_program(fakes / "blender", "echo 'Error: no such node' >&2\nexit 1\n");
  const PathSetting path(fakes.path().string());
  const test::CommandResult r = test::run_eyestream(kBench);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(line_of(r.output, "blender fog glow").find("skipped: failed: exit 1: Error: no such node"),
            std::string::npos)
      << r.output;
  EXPECT_NE(line_of(r.output, "pfstmo_pattanaik00 -t").find("skipped: not installed"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace eyestream
