// MP4 files as players expect them: the index ('moov') before the media
// ('mdat') so a file plays while it downloads, and HEVC tagged 'hvc1'
// (Apple's players refuse 'hev1'). Read from the file's top-level boxes
// here, not by eyestream.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "tests/test_support.hpp"

namespace eyestream {
namespace {

// The types of the top-level boxes, in order.
std::vector<std::string> top_level_boxes(const std::string& bytes) {
  std::vector<std::string> types;
  size_t at = 0;
  while (at + 8 <= bytes.size()) {
    std::uint64_t size = 0;
    for (int i = 0; i < 4; ++i) size = size << 8 | static_cast<unsigned char>(bytes[at + size_t(i)]);
    const std::string type = bytes.substr(at + 4, 4);
    if (size == 1 && at + 16 <= bytes.size()) {  // 64-bit size
      size = 0;
      for (int i = 0; i < 8; ++i) size = size << 8 | static_cast<unsigned char>(bytes[at + 8 + size_t(i)]);
    }
    types.push_back(type);
    if (size < 8) break;
    at += size_t(size);
  }
  return types;
}

TEST(Mp4Layout, IndexFirstAndHevcTaggedHvc1) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 64 --height 36 --duration 0.3")
                .exit_code,
            0);
  for (const std::string extra : {"", " --bit-depth 10"}) {
    const auto r = test::run_eyestream("run -y -i " + (dir / "h/frames") + " -o " + (dir / "v.mp4") + extra);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string bytes = test::read_bytes(dir / "v.mp4");
    const std::vector<std::string> boxes = top_level_boxes(bytes);
    const auto moov = std::find(boxes.begin(), boxes.end(), "moov"), mdat = std::find(boxes.begin(), boxes.end(), "mdat");
    ASSERT_NE(moov, boxes.end()) << extra;
    ASSERT_NE(mdat, boxes.end()) << extra;
    EXPECT_LT(moov - boxes.begin(), mdat - boxes.begin()) << "index before media" << extra;
    if (!extra.empty()) {
      EXPECT_NE(bytes.find("hvc1"), std::string::npos);
      EXPECT_EQ(bytes.find("hev1"), std::string::npos);
    }
  }
}

// The 'clli' box's MaxCLL and MaxFALL (big-endian after the box type), or
// -1s when there is none.
std::pair<int, int> clli(const std::string& bytes) {
  const size_t at = bytes.find("clli");
  if (at == std::string::npos || at + 8 > bytes.size()) return {-1, -1};
  auto u16 = [&](size_t i) { return int(static_cast<unsigned char>(bytes[i])) << 8 | static_cast<unsigned char>(bytes[i + 1]); };
  return {u16(at + 4), u16(at + 6)};
}

// `concat` joins HDR10 chunks into what `run` would have written: index
// first, 'hvc1', the mastering display, and the largest of the chunks'
// content light levels.
TEST(Mp4Layout, ConcatKeepsTheIndexFirstHvc1AndTheHdrMetadata) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 64 --height 36 --duration 0.4")
                .exit_code,
            0);
  const std::string run = "run -i " + (dir / "h/frames") + " --hdr10 --display-peak 1000 --preroll 0";
  ASSERT_EQ(test::run_eyestream(run + " -o " + (dir / "a.mp4") + " --end-frame 6").exit_code, 0);
  ASSERT_EQ(test::run_eyestream(run + " -o " + (dir / "b.mp4") + " --start-frame 6").exit_code, 0);
  const auto r = test::run_eyestream("concat -o " + (dir / "ab.mp4") + " " + (dir / "a.mp4") + " " + (dir / "b.mp4"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string bytes = test::read_bytes(dir / "ab.mp4");
  const std::vector<std::string> boxes = top_level_boxes(bytes);
  const auto moov = std::find(boxes.begin(), boxes.end(), "moov"), mdat = std::find(boxes.begin(), boxes.end(), "mdat");
  ASSERT_NE(moov, boxes.end());
  ASSERT_NE(mdat, boxes.end());
  EXPECT_LT(moov - boxes.begin(), mdat - boxes.begin()) << "index before media";
  EXPECT_NE(bytes.find("hvc1"), std::string::npos);
  EXPECT_EQ(bytes.find("hev1"), std::string::npos);
  EXPECT_NE(bytes.find("mdcv"), std::string::npos) << "mastering display";
  const auto a = clli(test::read_bytes(dir / "a.mp4")), b = clli(test::read_bytes(dir / "b.mp4")), ab = clli(bytes);
  ASSERT_GT(a.first, 0);
  ASSERT_GT(b.first, 0);
  EXPECT_EQ(ab.first, std::max(a.first, b.first));
  EXPECT_EQ(ab.second, std::max(a.second, b.second));
}

}  // namespace
}  // namespace eyestream
