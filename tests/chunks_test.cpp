// Chunked scale-out: the plan, and chunk outputs against one sequential run.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "io/error.hpp"
#include "io/video_reader.hpp"
#include "pipeline/run/chunk_plan.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

using pipeline::ChunkRequest;
using pipeline::plan_chunks;

TEST(Chunks, PlanCoversEveryFrameOnceWithThePreroll) {
  ChunkRequest r;
  r.input = "in/%05d.exr";
  r.output = "out/chunk_%02d.mp4";
  r.chunk_frames = 70;
  r.preroll_s = 7.5;
  r.run_options = {"-g", "my gaze.csv"};
  const auto chunks = plan_chunks(r, 180);
  ASSERT_EQ(chunks.size(), 3u);
  EXPECT_EQ(chunks[0].start, 0);
  EXPECT_EQ(chunks[1].start, 70);
  EXPECT_EQ(chunks[2].end, 180);
  EXPECT_EQ(chunks[2].output, "out/chunk_02.mp4");
  EXPECT_EQ(chunks[1].command,
            "eyestream run -i in/%05d.exr -o out/chunk_01.mp4 --start-frame 70 --end-frame 140 --preroll 7.5 -g "
            "'my gaze.csv'");
  r.output = "out/whole.mp4";
  EXPECT_THROW(plan_chunks(r, 180), UsageError) << "chunk videos need a chunk number";
  r.output = "out/%05d.png";
  EXPECT_EQ(plan_chunks(r, 180)[2].output, "out/%05d.png") << "frame patterns are shared";
  EXPECT_THROW(plan_chunks(r, -1), UsageError) << "unknown length";
}

// Chunks run one after another into one frame pattern give the sequential
// output byte for byte when each pre-roll reaches the start; without a
// pre-roll the later chunks differ (the state's history matters).
TEST(Chunks, ChunkedFramesMatchTheSequentialRunWithAFullPreroll) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample night-drive -o " + (dir / "nd") + " --width 96 --height 54 --duration 1.5")
                .exit_code,
            0);
  const std::string in = "-i " + (dir / "nd/frames") + " -g " + (dir / "nd/gaze.csv");
  ASSERT_EQ(test::run_eyestream("run " + in + " -o " + (dir / "seq/%05d.png")).exit_code, 0);
  for (const char* preroll : {"1.5", "0"}) {
    const std::string out = dir / (std::string("c") + preroll + "/%05d.png");
    const auto plan = test::run_eyestream("chunks " + in.substr(0, in.find(" -g ")) + " -o " + out +
                                          " --chunk-frames 20 --preroll " + preroll + " -- -g " + (dir / "nd/gaze.csv"));
    ASSERT_EQ(plan.exit_code, 0) << plan.output;
    std::istringstream lines(plan.output);
    int commands = 0;
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("eyestream:", 0) == 0) continue;  // the summary on stderr
      ASSERT_EQ(std::system((line + " > /dev/null 2>&1").c_str()), 0) << line;
      ++commands;
    }
    EXPECT_EQ(commands, 3) << plan.output;
    const auto same = test::run_eyestream("compare " + (dir / "seq") + " " + out + " --metric max --warn 0 --fail 0");
    if (std::string(preroll) == "0")
      EXPECT_EQ(same.exit_code, 2) << "no pre-roll: later chunks start from a fresh eye";
    else
      EXPECT_EQ(same.exit_code, 0) << same.output;
  }
}

// Chunk videos join without re-encoding: the joined file decodes to the
// chunks' own pictures, in order, with their times; chunks out of order
// are refused.
TEST(Chunks, ChunkVideosJoinLosslessly) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample flash -o " + (dir / "s") + " --width 64 --height 48 --duration 1").exit_code,
            0);
  std::vector<std::string> parts;
  for (int k = 0; k < 3; ++k) {
    const std::string out = dir / ("part" + std::to_string(k) + ".mp4");
    const auto r = test::run_eyestream("run -i " + (dir / "s/frames") + " -o " + out + " --start-frame " +
                                       std::to_string(10 * k) + " --end-frame " + std::to_string(10 * k + 10) +
                                       " --preroll 1");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    parts.push_back(out);
  }
  auto r = test::run_eyestream("concat -o " + (dir / "all.mp4") + " " + parts[0] + " " + parts[1] + " " + parts[2]);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  io::VideoReader joined(dir / "all.mp4");
  int frames = 0;
  for (const std::string& part : parts) {
    io::VideoReader chunk(part);
    while (auto expected = chunk.next()) {
      const auto got = joined.next();
      ASSERT_TRUE(got) << frames;
      EXPECT_EQ(cv::norm(got->rgb, expected->rgb, cv::NORM_INF), 0.0) << "frame " << frames;
      EXPECT_NEAR(got->time_s, frames / 30.0, 1e-3);
      ++frames;
    }
  }
  EXPECT_EQ(frames, 30);
  EXPECT_FALSE(joined.next());
  r = test::run_eyestream("concat -o " + (dir / "bad.mp4") + " " + parts[1] + " " + parts[0]);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.mp4"));
}

// Matroska chunks (presentation times only) join too, into MKV or MP4; a
// missing chunk and a chunk made with other colour settings are refused,
// naming the chunk.
TEST(Chunks, MatroskaChunksJoinAndAMissingOrMismatchedChunkIsRefused) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample flash -o " + (dir / "s") + " --width 64 --height 48 --duration 1").exit_code,
            0);
  const auto part = [&](int k, const std::string& extra) {
    const std::string out = dir / ("p" + std::to_string(k) + "_" + std::to_string(extra.size()) + ".mkv");
    const auto r = test::run_eyestream("run -i " + (dir / "s/frames") + " -o " + out + " --start-frame " +
                                       std::to_string(10 * k) + " --end-frame " + std::to_string(10 * k + 10) +
                                       " --preroll 0" + extra);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return out;
  };
  const std::string a = part(0, ""), b = part(1, ""), c = part(2, ""), hdr = part(1, " --hdr10"),
                    other_crf = part(1, " --crf 30");
  for (const char* ext : {".mkv", ".mp4"}) {
    const std::string joined = dir / (std::string("all") + ext);
    const auto r = test::run_eyestream("concat -o " + joined + " " + a + " " + b + " " + c);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    io::VideoReader v(joined);
    int frames = 0;
    while (v.next()) ++frames;
    EXPECT_EQ(frames, 30) << ext;
  }
  auto r = test::run_eyestream("concat -o " + (dir / "gap.mkv") + " " + a + " " + c);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("is a chunk missing between them?"), std::string::npos) << r.output;
  r = test::run_eyestream("concat -o " + (dir / "mix.mkv") + " " + a + " " + hdr);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  r = test::run_eyestream("concat -o " + (dir / "crf.mkv") + " " + a + " " + other_crf);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("its codec headers differ"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "mix.mkv"));
}

}  // namespace
}  // namespace eyestream
