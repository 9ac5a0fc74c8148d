// --exr-compression through the command line: each name gives EXR frames
// that OpenEXR itself (read here, not through the project's reader) says
// carry that compression, with the same float pixels as every other name.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfCompression.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "tests/test_support.hpp"

namespace eyestream {
namespace {

struct ExrContents {
  Imf::Compression compression = Imf::NUM_COMPRESSION_METHODS;
  std::vector<float> rgb;
};

// The file's compression and its R, G and B planes one after the other.
ExrContents read_with_openexr(const std::string& path) {
  ExrContents c;
  c.compression = Imf::InputFile(path.c_str()).header().compression();
  for (const char* name : {"R", "G", "B"}) {
    const std::vector<float> plane = test::openexr_channel(path, name);
    c.rgb.insert(c.rgb.end(), plane.begin(), plane.end());
  }
  return c;
}

TEST(ExrCompression, EachNameIsTheFilesCompressionAndThePixelsAreTheSame) {
  test::ScratchDir dir;
  const std::string scene = dir / "s";
  ASSERT_EQ(test::run_eyestream("sample night-drive -o " + scene + " --width 96 --height 54 --duration 0.1").exit_code,
            0);
  const std::map<std::string, Imf::Compression> names = {{"zip", Imf::ZIP_COMPRESSION},
                                                         {"zips", Imf::ZIPS_COMPRESSION},
                                                         {"piz", Imf::PIZ_COMPRESSION},
                                                         {"rle", Imf::RLE_COMPRESSION},
                                                         {"none", Imf::NO_COMPRESSION}};
  const std::string in = "-i " + scene + "/frames -g " + scene + "/gaze.csv";
  ASSERT_EQ(test::run_eyestream("run " + in + " -o " + (dir / "default/%05d.exr")).exit_code, 0);
  const ExrContents by_default = read_with_openexr(dir / "default/00002.exr");
  EXPECT_EQ(by_default.compression, Imf::ZIP_COMPRESSION) << "zip unless asked";
  bool lit = false;
  for (float v : by_default.rgb) lit = lit || v > 0.001f;
  EXPECT_TRUE(lit) << "a frame with something in it";
  for (const auto& [name, compression] : names) {
    const auto r = test::run_eyestream("run " + in + " -o " + (dir / (name + "/%05d.exr")) + " --exr-compression " + name);
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.output;
    for (const char* frame : {"00000.exr", "00002.exr"}) {
      const ExrContents c = read_with_openexr(dir / (name + "/" + frame));
      EXPECT_EQ(c.compression, compression) << name;
      const ExrContents zip = read_with_openexr(dir / (std::string("default/") + frame));
      EXPECT_TRUE(c.rgb == zip.rgb) << name << " " << frame << ": lossless, the same floats";
    }
  }
}

TEST(ExrCompression, AnUnknownNameIsAUsageErrorNamingTheParameter) {
  test::ScratchDir dir;
  const auto r = test::run_eyestream("run -i " + (dir / "f_%05d.exr") + " -o " + (dir / "o/%05d.exr") +
                                     " --exr-compression dwaa");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("eyestream: error:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("exr-compression"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace eyestream
