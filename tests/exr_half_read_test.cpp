// EXR files whose channels are half floats (as most are) read through the
// half rows (io/half_rows.hpp), against Imath's conversion of the halves
// written, bit for bit: RGB in several bands of lines with a data window
// off the origin, luminance only, a layer's channels beside other ones, a
// tiled file, and a file mixing half and float channels (read by OpenEXR's
// own conversion), each written here with OpenEXR.
#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfTiledOutputFile.h>
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "io/exr_file.hpp"
#include "retina/bit_masks.hpp"
#include "tests/test_support.hpp"

namespace eyestream::io {
namespace {

// One channel's values in a data window: halves (bits) or floats.
struct Plane {
  Imf::PixelType type = Imf::HALF;
  std::vector<std::uint16_t> halves;
  std::vector<float> floats;
  float value(size_t i) const {
    if (type == Imf::FLOAT) return floats[i];
    Imath::half h;
    h.setBits(halves[i]);
    return float(h);
  }
};

// Random values of every kind: magnitudes from subnormal to the largest
// half, zeros of both signs, infinities and NaNs.
Plane random_plane(Imf::PixelType type, size_t n, std::mt19937& random) {
  Plane p;
  p.type = type;
  std::uniform_int_distribution<int> bits_of(0, 65535);
  for (size_t i = 0; i < n; ++i) {
    Imath::half h;
    h.setBits(std::uint16_t(bits_of(random)));
    if (type == Imf::HALF)
      p.halves.push_back(h.bits());
    else
      p.floats.push_back(float(h) * 1.25f);
  }
  return p;
}

void write_file(const std::string& path, const Imath::Box2i& window, const std::map<std::string, Plane>& planes,
                bool tiled) {
  Imf::Header header(window, window);
  for (const auto& [name, plane] : planes) header.channels().insert(name, Imf::Channel(plane.type));
  if (tiled) header.setTileDescription(Imf::TileDescription(16, 16, Imf::ONE_LEVEL));
  const int width = window.max.x - window.min.x + 1;
  Imf::FrameBuffer fb;
  for (const auto& [name, plane] : planes) {
    const void* data = plane.type == Imf::HALF ? static_cast<const void*>(plane.halves.data()) : plane.floats.data();
    const size_t size = plane.type == Imf::HALF ? 2 : 4;
    fb.insert(name, Imf::Slice::Make(plane.type, data, window, size, size * size_t(width)));
  }
  if (tiled) {
    Imf::TiledOutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
  } else {
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(window.max.y - window.min.y + 1);
  }
}

using retina::bits_of;

// Reads the file and checks every pixel's three values against the
// planes: red, green, blue (or the one grey plane in all three).
void expect_read(const std::string& path, const std::string& layer, const std::vector<const Plane*>& rgb, int width,
                 int height) {
  const ExrImage image = read_exr(path, 1 << 24, layer);
  ASSERT_EQ(image.rgb.size(), cv::Size(width, height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        const size_t i = size_t(y) * size_t(width) + size_t(x);
        const float want = rgb[rgb.size() == 1 ? 0 : size_t(c)]->value(i);
        ASSERT_EQ(bits_of(image.rgb.at<cv::Vec3f>(y, x)[c]), bits_of(want))
            << path << " x " << x << " y " << y << " c " << c;
      }
}

TEST(ExrHalfRead, EveryLayoutGivesImathsValuesBitForBit) {
  test::ScratchDir dir;
  std::mt19937 random(17);
  const Imath::Box2i window(Imath::V2i(5, -7), Imath::V2i(5 + 36, -7 + 39));  // 37 x 40: three bands of 16 lines
  const int w = 37, h = 40;
  const size_t n = size_t(w) * size_t(h);
  const Plane r = random_plane(Imf::HALF, n, random), g = random_plane(Imf::HALF, n, random),
              b = random_plane(Imf::HALF, n, random), grey = random_plane(Imf::HALF, n, random),
              g_float = random_plane(Imf::FLOAT, n, random);

  write_file(dir / "rgb.exr", window, {{"R", r}, {"G", g}, {"B", b}}, false);
  expect_read(dir / "rgb.exr", "", {&r, &g, &b}, w, h);

  write_file(dir / "tiled.exr", window, {{"R", r}, {"G", g}, {"B", b}}, true);
  expect_read(dir / "tiled.exr", "", {&r, &g, &b}, w, h);

  write_file(dir / "y.exr", window, {{"Y", grey}}, false);
  expect_read(dir / "y.exr", "", {&grey}, w, h);

  // A layer's channels, with the beauty pass's beside them.
  write_file(dir / "layers.exr", window,
             {{"R", grey}, {"G", grey}, {"B", grey}, {"Lit.R", r}, {"Lit.G", g}, {"Lit.B", b}}, false);
  expect_read(dir / "layers.exr", "Lit", {&r, &g, &b}, w, h);
  expect_read(dir / "layers.exr", "", {&grey, &grey, &grey}, w, h);

  // Half and float channels together: OpenEXR's conversion.
  write_file(dir / "mixed.exr", window, {{"R", r}, {"G", g_float}, {"B", b}}, false);
  expect_read(dir / "mixed.exr", "", {&r, &g_float, &b}, w, h);
}

}  // namespace
}  // namespace eyestream::io
