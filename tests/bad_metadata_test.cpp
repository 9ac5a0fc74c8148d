// Metadata and headers that used to crash, allocate gigabytes or silently
// give black frames: each refused before decoding, exit 3, one line naming
// the file and the attribute.
#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>

#include <sys/resource.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <vector>

#include "io/exr_file.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

namespace fs = std::filesystem;

class BadMetadata : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(dir_ / "gaze.csv") << "t,x,y\n0,8,6\n"; }
  // Runs on `input`; the exit code, a part of the one error line, and nothing written.
  void expect_refused(const std::string& input, const std::string& message) {
    const auto r = test::run_eyestream("run -i " + input + " -g " + (dir_ / "gaze.csv") + " -o " + (dir_ / "out.mp4"));
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_EQ(r.output.rfind("eyestream: error: ", 0), 0u) << "one error line, nothing before it: " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "out.mp4"));
  }
  test::ScratchDir dir_;
};

TEST_F(BadMetadata, ANegativeWhiteLuminanceIsRefused) {
  io::write_exr(dir_ / "w.exr", test::constant_frame(16, 12, {1, 1, 1}), {false, -5.0, 30.0});
  expect_refused(dir_ / "w.exr", "w.exr: whiteLuminance -5");
}

TEST_F(BadMetadata, AnAbsurdFrameRateIsRefused) {
  io::write_exr(dir_ / "f.exr", test::constant_frame(16, 12, {1, 1, 1}), {false, std::nullopt, 7e-9});
  expect_refused(dir_ / "f.exr", "f.exr: framesPerSecond");
}

TEST_F(BadMetadata, SingularChromaticitiesAreRefused) {
  // Three primaries on one line: no RGB space.
  Imf::Header header(16, 12);
  header.channels().insert("R", Imf::Channel(Imf::FLOAT));
  header.channels().insert("G", Imf::Channel(Imf::FLOAT));
  header.channels().insert("B", Imf::Channel(Imf::FLOAT));
  Imf::addChromaticities(header, Imf::Chromaticities({0.2f, 0.2f}, {0.3f, 0.3f}, {0.4f, 0.4f}, {0.3127f, 0.329f}));
  std::vector<float> rgb(16 * 12 * 3, 1.0f);
  Imf::FrameBuffer fb;
  char* base = reinterpret_cast<char*>(rgb.data());
  for (int c = 0; c < 3; ++c)
    fb.insert(c == 0 ? "R" : c == 1 ? "G" : "B",
              Imf::Slice(Imf::FLOAT, base + c * sizeof(float), 3 * sizeof(float), 3 * sizeof(float) * 16));
  {
    Imf::OutputFile file((dir_ / "c.exr").c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(12);
  }
  expect_refused(dir_ / "c.exr", "c.exr: chromaticities");
}

TEST_F(BadMetadata, APfmWithANegativeSizeIsRefused) {
  std::ofstream(dir_ / "n.pfm", std::ios::binary) << "PF\n-16 12\n-1.0\n" << std::string(64, '\0');
  expect_refused(dir_ / "n.pfm", "n.pfm: declares a size of -16x12");
}

TEST_F(BadMetadata, ATinyPfmClaimingAHugeImageIsRefusedBeforeDecoding) {
  std::ofstream(dir_ / "h.pfm", std::ios::binary) << "PF\n100000 100000\n-1.0\n" << std::string(1000, '\0');
  expect_refused(dir_ / "h.pfm", "h.pfm: 100000x100000 exceeds the limit");
}

TEST_F(BadMetadata, ATinyHdrClaimingAHugeImageIsRefusedBeforeDecoding) {
  std::ofstream(dir_ / "h.hdr", std::ios::binary) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 90000 +X 90000\n"
                                                  << std::string(1000, '\0');
  expect_refused(dir_ / "h.hdr", "h.hdr: 90000x90000 exceeds the limit");
}

// An EXR of a few hundred bytes whose header claims a data window of 800
// million pixels is refused from its header, before OpenEXR builds its tables
// for it: the run's peak memory stays small.
TEST_F(BadMetadata, AnExrClaimingAHugeDataWindowIsRefusedFromItsHeader) {
  io::write_exr(dir_ / "big.exr", test::constant_frame(16, 12, {1, 1, 1}), {false, std::nullopt, 30.0});
  std::string bytes = test::read_bytes(dir_ / "big.exr");
  const std::string key = std::string("dataWindow") + '\0' + "box2i" + '\0';
  const size_t at = bytes.find(key);
  ASSERT_NE(at, std::string::npos);
  const std::int32_t huge = 49999999;  // ymax: 16 x 50 million pixels
  std::memcpy(&bytes[at + key.size() + 4 + 12], &huge, 4);
  std::ofstream(dir_ / "big.exr", std::ios::binary | std::ios::trunc) << bytes;
  expect_refused(dir_ / "big.exr", "big.exr: data window 16x50000000 (read from its header) exceeds the limit");
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  EXPECT_LT(usage.ru_maxrss, 400 * 1024) << "peak resident memory of the run, KiB";
}

TEST_F(BadMetadata, RawFramesLargerThanTheGuardAreRefusedBeforeAllocating) {
  const auto r = test::run_eyestream("run -i - --size 65536x65536 -g " + (dir_ / "gaze.csv") + " -o " +
                                     (dir_ / "out.mp4") + " < /dev/null");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--size 65536x65536 exceeds the limit"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace eyestream
