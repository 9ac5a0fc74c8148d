// Outputs say what they hold: PNG frames carry gAMA (the display encoding's
// power, --gamma) and cHRM (Rec.709, D65) chunks, checked by walking the file's
// chunks with zlib's CRC-32 as the oracle, and EXR frames carry the run's
// frame rate.
#include <gtest/gtest.h>
#include <zlib.h>

#include <opencv2/imgcodecs.hpp>

#include "io/exr_file.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

std::uint32_t be32(const std::string& b, size_t at) {
  return std::uint32_t(std::uint8_t(b[at])) << 24 | std::uint32_t(std::uint8_t(b[at + 1])) << 16 |
         std::uint32_t(std::uint8_t(b[at + 2])) << 8 | std::uint32_t(std::uint8_t(b[at + 3]));
}

struct Chunk {
  std::string type;
  std::vector<std::uint32_t> words;
};

// Every chunk of a PNG file, each CRC checked with zlib.
std::vector<Chunk> chunks_of(const std::string& png) {
  std::vector<Chunk> out;
  EXPECT_EQ(png.substr(1, 3), "PNG");
  for (size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t n = be32(png, at);
    Chunk c{png.substr(at + 4, 4), {}};
    const uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(png.data() + at + 4), uInt(n + 4));
    EXPECT_EQ(crc, be32(png, at + 8 + n)) << c.type << " CRC";
    for (size_t w = 0; w + 4 <= n && c.type != "IDAT"; w += 4) c.words.push_back(be32(png, at + 8 + w));
    out.push_back(c);
    at += 12 + n;
  }
  return out;
}

TEST(OutputTags, PngFramesCarryGammaAndChromaticitiesExrFramesTheirRate) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 48 --height 27 --duration 0.1")
                .exit_code,
            0);
  for (const char* bits : {"8", "16"}) {
    const std::string out = dir / (std::string("p") + bits);
    const auto r = test::run_eyestream("run -i " + (dir / "h/frames") + " --fps 24 -o " + out + "/%05d.png --png-bits " +
                                       bits);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::vector<Chunk> chunks = chunks_of(test::read_bytes(out + "/00000.png"));
    std::vector<std::string> order;
    for (const Chunk& c : chunks) order.push_back(c.type);
    ASSERT_GE(order.size(), 5u);
    EXPECT_EQ(order[0], "IHDR");
    EXPECT_EQ(order[1], "gAMA");
    EXPECT_EQ(order[2], "cHRM");
    EXPECT_EQ(order.back(), "IEND");
    EXPECT_EQ(chunks[1].words, std::vector<std::uint32_t>{45500}) << "the default encoding, code = light^0.455";
    EXPECT_EQ(chunks[2].words, (std::vector<std::uint32_t>{31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000}));
    EXPECT_FALSE(cv::imread(out + "/00000.png", cv::IMREAD_UNCHANGED).empty());
  }
  // Another encoding power, another gAMA.
  ASSERT_EQ(test::run_eyestream("run -i " + (dir / "h/frames") + " -o " + (dir / "g/%05d.png") + " --gamma 0.6").exit_code,
            0);
  EXPECT_EQ(chunks_of(test::read_bytes(dir / "g/00000.png"))[1].words, std::vector<std::uint32_t>{60000});
  ASSERT_EQ(test::run_eyestream("run -i " + (dir / "h/frames") + " --fps 24 -o " + (dir / "e/%05d.exr")).exit_code, 0);
  const io::ExrImage e = io::read_exr(dir / "e/00000.exr", 1000000);
  ASSERT_TRUE(e.frames_per_second.has_value());
  EXPECT_DOUBLE_EQ(*e.frames_per_second, 24.0);
}

}  // namespace
}  // namespace eyestream
