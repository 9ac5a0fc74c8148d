#include "io/frame_sequence.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "io/error.hpp"
#include "tests/test_support.hpp"

namespace eyestream::io {
namespace {

void touch(const std::string& path) { std::ofstream(path) << "x"; }

TEST(FrameSequence, FormatsPrintfPatterns) {
  EXPECT_EQ(format_pattern("a/f_%05d.exr", 42), "a/f_00042.exr");
  EXPECT_EQ(format_pattern("f%d.exr", 7), "f7.exr");
  EXPECT_TRUE(is_printf_pattern("x/%04d.png"));
  EXPECT_FALSE(is_printf_pattern("x/still.exr"));
}

TEST(FrameSequence, ListsNumberedFramesInOrder) {
  test::ScratchDir dir;
  for (int n : {12, 10, 11}) touch(format_pattern(dir / "f_%03d.exr", n));
  touch(dir / "f_other.exr");
  const auto list = list_sequence(dir / "f_%03d.exr", {".exr"}, false);
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0].number, 10);
  EXPECT_EQ(list[2].path, dir / "f_012.exr");
}

TEST(FrameSequence, MissingFrameNamesTheFirstMissingFile) {
  test::ScratchDir dir;
  for (int n : {1, 2, 5, 6}) touch(format_pattern(dir / "f_%03d.exr", n));
  try {
    list_sequence(dir / "f_%03d.exr", {".exr"}, false);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f_003.exr"), std::string::npos) << e.what();
  }
  const auto list = list_sequence(dir / "f_%03d.exr", {".exr"}, true);
  ASSERT_EQ(list.size(), 4u);
  EXPECT_EQ(list[2].number, 5);
}

TEST(FrameSequence, FolderListsItsExrFilesByName) {
  test::ScratchDir dir;
  touch(dir / "b.exr");
  touch(dir / "a.EXR");
  touch(dir / "notes.txt");
  const auto list = list_sequence(dir.path().string(), {".exr"}, false);
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].path, dir / "a.EXR");
}

TEST(FrameSequence, NothingToReadIsAnInputError) {
  test::ScratchDir dir;
  EXPECT_THROW(list_sequence(dir / "none_%04d.exr", {".exr"}, false), InputError);
  EXPECT_THROW(list_sequence(dir / "none.exr", {".exr"}, false), InputError);
}

}  // namespace
}  // namespace eyestream::io
