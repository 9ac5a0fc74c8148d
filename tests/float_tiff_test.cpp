// Float TIFF stills as other tools write them, built byte by byte here (no
// libtiff, no OpenCV writer): half floats, RGBA with an alpha extra sample,
// and grey + alpha in separate planes, each read as the light it holds.
#include <gtest/gtest.h>

#include <Imath/half.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

#include "io/error.hpp"
#include "io/float_tiff.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

struct Tag {
  std::uint16_t id, type;  // type 3 SHORT, 4 LONG
  std::vector<std::uint32_t> values;
};

void put(std::vector<unsigned char>& b, std::uint32_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) b.push_back(static_cast<unsigned char>(v >> (8 * i)));
}

// A little-endian classic TIFF with one IFD: `tags` and the data chunks
// (strips, or tiles when `tiled`), in libtiff's order; their offsets and
// byte counts are filled in here.
std::vector<unsigned char> tiff_file(std::vector<Tag> tags, const std::vector<std::vector<unsigned char>>& strips,
                                     bool tiled = false) {
  const std::uint16_t offsets_tag = tiled ? 324 : 273, counts_tag = tiled ? 325 : 279;
  tags.push_back({offsets_tag, 4, std::vector<std::uint32_t>(strips.size())});
  std::vector<std::uint32_t> counts;
  for (const auto& s : strips) counts.push_back(std::uint32_t(s.size()));
  tags.push_back({counts_tag, 4, counts});
  std::sort(tags.begin(), tags.end(), [](const Tag& a, const Tag& b) { return a.id < b.id; });
  const auto size_of = [](const Tag& t) { return t.values.size() * (t.type == 3 ? 2 : 4); };
  const std::uint32_t ifd_end = 8 + 2 + 12 * std::uint32_t(tags.size()) + 4;
  std::uint32_t external = ifd_end;
  for (const Tag& t : tags) external += size_of(t) > 4 ? std::uint32_t(size_of(t)) : 0;
  std::uint32_t at = external;
  for (Tag& t : tags)
    if (t.id == offsets_tag)
      for (size_t k = 0; k < strips.size(); ++k) t.values[k] = at, at += std::uint32_t(strips[k].size());
  std::vector<unsigned char> b = {'I', 'I', 42, 0, 8, 0, 0, 0};
  put(b, std::uint32_t(tags.size()), 2);
  std::vector<unsigned char> outside;
  for (const Tag& t : tags) {
    put(b, t.id, 2);
    put(b, t.type, 2);
    put(b, std::uint32_t(t.values.size()), 4);
    std::vector<unsigned char> v;
    for (std::uint32_t x : t.values) put(v, x, t.type == 3 ? 2 : 4);
    if (v.size() <= 4) {
      v.resize(4, 0);
      b.insert(b.end(), v.begin(), v.end());
    } else {
      put(b, ifd_end + std::uint32_t(outside.size()), 4);
      outside.insert(outside.end(), v.begin(), v.end());
    }
  }
  put(b, 0, 4);  // no next IFD
  b.insert(b.end(), outside.begin(), outside.end());
  for (const auto& s : strips) b.insert(b.end(), s.begin(), s.end());
  return b;
}

std::vector<unsigned char> halves(const std::vector<float>& v) {
  std::vector<unsigned char> b;
  for (float f : v) put(b, Imath::half(f).bits(), 2);
  return b;
}

std::vector<unsigned char> floats(const std::vector<float>& v) {
  std::vector<unsigned char> b;
  for (float f : v) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    put(b, u, 4);
  }
  return b;
}

std::string write(const test::ScratchDir& dir, const std::string& name, const std::vector<unsigned char>& bytes) {
  std::ofstream(dir / name, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  return dir / name;
}

// 2x1 images: pixel 0 and pixel 1.
std::vector<Tag> base(std::uint32_t spp, std::uint32_t bits, std::uint32_t photometric, std::uint32_t planar) {
  return {{256, 4, {2}},  {257, 4, {1}}, {258, 3, std::vector<std::uint32_t>(spp, bits)}, {259, 3, {1}},
          {262, 3, {photometric}}, {277, 3, {spp}}, {278, 4, {1}}, {284, 3, {planar}},
          {339, 3, std::vector<std::uint32_t>(spp, 3)}};
}

TEST(FloatTiff, HalfFloatRgbIsReadAsItsLight) {
  test::ScratchDir dir;
  const auto path = write(dir, "half.tif", tiff_file(base(3, 16, 2, 1), {halves({0.5f, 100.0f, 2048.0f, 1.0f, 2.0f, 3.0f})}));
  const cv::Mat rgb = io::read_float_tiff(path);
  ASSERT_EQ(rgb.size(), cv::Size(2, 1));
  EXPECT_EQ(rgb.at<cv::Vec3f>(0, 0), cv::Vec3f(0.5f, 100.0f, 2048.0f));
  EXPECT_EQ(rgb.at<cv::Vec3f>(0, 1), cv::Vec3f(1.0f, 2.0f, 3.0f));
}

TEST(FloatTiff, RgbaWithAnAlphaExtraSampleDropsTheAlpha) {
  test::ScratchDir dir;
  std::vector<Tag> tags = base(4, 32, 2, 1);
  tags.push_back({338, 3, {2}});  // ExtraSamples: unassociated alpha
  const auto path = write(dir, "rgba.tif", tiff_file(tags, {floats({7, 8, 9, 0.5f, 10, 20, 30, 1})}));
  const cv::Mat rgb = io::read_float_tiff(path);
  EXPECT_EQ(rgb.at<cv::Vec3f>(0, 0), cv::Vec3f(7, 8, 9));
  EXPECT_EQ(rgb.at<cv::Vec3f>(0, 1), cv::Vec3f(10, 20, 30));
}

TEST(FloatTiff, GreyAndAlphaInSeparatePlanesIsGrey) {
  test::ScratchDir dir;
  std::vector<Tag> tags = base(2, 32, 1, 2);
  tags.push_back({338, 3, {2}});
  const auto path = write(dir, "grey.tif", tiff_file(tags, {floats({40, 50}), floats({1, 1})}));
  const cv::Mat rgb = io::read_float_tiff(path);
  EXPECT_EQ(rgb.at<cv::Vec3f>(0, 0), cv::Vec3f(40, 40, 40));
  EXPECT_EQ(rgb.at<cv::Vec3f>(0, 1), cv::Vec3f(50, 50, 50));
}

// Tiles, 16x16, over a 20x18 image (edge tiles padded), in two planes of
// grey and alpha: every pixel's value is its own position.
TEST(FloatTiff, TiledPlanarImagesWithPartialEdgeTiles) {
  test::ScratchDir dir;
  const int w = 20, h = 18, tile = 16;
  std::vector<Tag> tags = {{256, 4, {std::uint32_t(w)}}, {257, 4, {std::uint32_t(h)}}, {258, 3, {32, 32}},
                           {259, 3, {1}}, {262, 3, {1}}, {277, 3, {2}}, {284, 3, {2}},
                           {322, 4, {std::uint32_t(tile)}}, {323, 4, {std::uint32_t(tile)}}, {338, 3, {2}},
                           {339, 3, {3, 3}}};
  std::vector<std::vector<unsigned char>> tiles;
  for (int plane = 0; plane < 2; ++plane)
    for (int ty = 0; ty < h; ty += tile)
      for (int tx = 0; tx < w; tx += tile) {
        std::vector<float> v(size_t(tile) * tile, -1.0f);  // padding beyond the image
        for (int y = 0; y < tile; ++y)
          for (int x = 0; x < tile; ++x)
            if (ty + y < h && tx + x < w) v[size_t(y) * tile + x] = plane == 0 ? float(100 * (ty + y) + tx + x) : 1.0f;
        tiles.push_back(floats(v));
      }
  const auto path = write(dir, "tiled.tif", tiff_file(tags, tiles, true));
  const cv::Mat rgb = io::read_float_tiff(path);
  ASSERT_EQ(rgb.size(), cv::Size(w, h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      ASSERT_EQ(rgb.at<cv::Vec3f>(y, x), cv::Vec3f::all(float(100 * y + x))) << x << ", " << y;
}

// Through the command line: one error line naming the file, no OpenCV or
// libtiff chatter, for an 8-bit TIFF (display code values, not light).
TEST(FloatTiff, AnIntegerTiffIsOneLineNamingItsSamples) {
  test::ScratchDir dir;
  std::vector<Tag> tags = base(3, 8, 2, 1);
  tags.back().values = {1, 1, 1};  // SampleFormat: unsigned integer
  write(dir, "code.tif", tiff_file(tags, {{1, 2, 3, 4, 5, 6}}));
  const auto r = test::run_eyestream("run -i " + (dir / "code.tif") + " -o " + (dir / "o.mp4"));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_EQ(r.output, "eyestream: error: " + (dir / "code.tif") +
                          ": holds 8-bit integer samples; eyestream reads 16- or 32-bit floating-point TIFFs "
                          "(linear light)\n");
}

}  // namespace
}  // namespace eyestream
