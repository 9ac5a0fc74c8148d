// Existing outputs are replaced only with -y (--overwrite), and an output a
// command cannot write in the format its name says is refused.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/test_support.hpp"

namespace eyestream {
namespace {

TEST(Overwrite, AnExistingOutputIsRefusedUnlessAskedAndLeftAsItWas) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 48 --height 27 --duration 0.2")
                .exit_code,
            0);
  const std::string run = "run -i " + (dir / "h/frames") + " --no-progress -o ";
  ASSERT_EQ(test::run_eyestream(run + (dir / "v.mp4")).exit_code, 0);
  std::filesystem::resize_file(dir / "v.mp4", 10);
  auto r = test::run_eyestream(run + (dir / "v.mp4"));
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("v.mp4 (-o) exists; pass -y (--overwrite)"), std::string::npos) << r.output;
  EXPECT_EQ(std::filesystem::file_size(dir / "v.mp4"), 10u) << "left as it was";
  r = test::run_eyestream(run + (dir / "v.mp4") + " -y");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_GT(std::filesystem::file_size(dir / "v.mp4"), 10u);
  // Frames: the ones the run would write count; a chunk writing other
  // frames of the same pattern goes ahead.
  ASSERT_EQ(test::run_eyestream(run + (dir / "f/%05d.png") + " --end-frame 3").exit_code, 0);
  r = test::run_eyestream(run + (dir / "f/%05d.png") + " --end-frame 3");
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("00000.png"), std::string::npos) << r.output;
  r = test::run_eyestream(run + (dir / "f/%05d.png") + " --start-frame 3");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::run_eyestream(run + (dir / "f/%05d.png") + " --overwrite").exit_code, 0);
}

// `sample` into a folder holding a scene: refused without -y; with -y the
// folder holds the new scene alone (a shorter one leaves no old frames).
TEST(Overwrite, ASampleReplacesAnotherOnlyWithYAndLeavesNoStaleFrames) {
  test::ScratchDir dir;
  const std::string sample = "sample night-drive -o " + (dir / "s") + " --width 32 --height 18 --fps 10 --duration ";
  ASSERT_EQ(test::run_eyestream(sample + "1").exit_code, 0);
  ASSERT_EQ(test::count_entries(dir.path() / "s/frames"), 10);
  auto r = test::run_eyestream(sample + "0.5");
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("exists; pass -y (--overwrite)"), std::string::npos) << r.output;
  EXPECT_EQ(test::count_entries(dir.path() / "s/frames"), 10) << "left as it was";
  r = test::run_eyestream(sample + "0.5 -y");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::count_entries(dir.path() / "s/frames"), 5) << "the longer scene's frames are gone";
}

TEST(Overwrite, AnOutputNamedForAnotherFormatIsRefused) {
  test::ScratchDir dir;
  auto r = test::run_eyestream("curves -o " + (dir / "c.svg"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("c.svg': writes .png only"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "c.svg"));
  r = test::run_eyestream("psf -o " + (dir / "k.png"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = test::run_eyestream("bench --csv " + (dir / "b.txt"));
  EXPECT_EQ(r.exit_code, 2) << "refused before any work: " << r.output;
  ASSERT_EQ(test::run_eyestream("curves -o " + (dir / "c.png")).exit_code, 0);
  EXPECT_EQ(test::run_eyestream("curves -o " + (dir / "c.png")).exit_code, 4);
  EXPECT_EQ(test::run_eyestream("curves -y -o " + (dir / "c.png")).exit_code, 0);
}

}  // namespace
}  // namespace eyestream
