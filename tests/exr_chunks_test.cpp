// EXR chunks decoded by the program (io/exr_chunks.hpp) against OpenEXR's
// own readPixels, computed here: files written by OpenEXR with ZIP, ZIPS
// and no compression, half RGB with other channels beside them (alpha, a
// float depth, an unsigned id, a layer), a data window off the origin,
// widths and heights that are not whole chunks, lines stored bottom up,
// smooth data and noise (whose chunks deflate cannot shrink and which are
// stored as they are). Other layouts are left to OpenEXR, and a damaged
// chunk is an InputError naming the file.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfCompression.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfOutputPart.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfOutputFile.h>
#include <gtest/gtest.h>

#include <Imath/half.h>

#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "io/error.hpp"
#include "io/exr_chunks.hpp"
#include "io/exr_file.hpp"
#include "tests/test_support.hpp"

namespace eyestream::io {
namespace {

struct Layout {
  Imf::Compression compression = Imf::ZIP_COMPRESSION;
  int width = 37, height = 35;
  Imath::V2i origin{0, 0};
  std::vector<std::pair<std::string, Imf::PixelType>> channels = {
      {"R", Imf::HALF}, {"G", Imf::HALF}, {"B", Imf::HALF}};
  bool noise = false;
  Imf::LineOrder order = Imf::INCREASING_Y;
};

// The value of channel c at (x, y): smooth, or noise.
float sample(const Layout& l, int c, int x, int y) {
  if (l.noise) {  // a finite half of random bits: nearly 16 bits of entropy
    std::mt19937 rng((unsigned(c) * 7919u + unsigned(y)) * 104729u + unsigned(x));  // unsigned: wraps, no overflow
    unsigned short bits = static_cast<unsigned short>(rng());
    if (((bits >> 10) & 31) == 31) bits &= 0xBFFF;  // not infinite or NaN
    Imath::half h;
    h.setBits(bits);
    return float(h);
  }
  return 0.01f * float(x + 1) * float(c + 1) + 3.0f * float(y);
}

void write(const std::string& path, const Layout& l) {
  const Imath::Box2i dw(l.origin, l.origin + Imath::V2i(l.width - 1, l.height - 1));
  Imf::Header header(dw, dw);
  header.compression() = l.compression;
  header.lineOrder() = l.order;
  for (const auto& [name, type] : l.channels) header.channels().insert(name, Imf::Channel(type));
  std::vector<std::vector<char>> planes;
  Imf::FrameBuffer fb;
  for (size_t c = 0; c < l.channels.size(); ++c) {
    const Imf::PixelType type = l.channels[c].second;
    const size_t bytes = type == Imf::HALF ? 2 : 4;
    planes.emplace_back(size_t(l.width) * size_t(l.height) * bytes);
    for (int y = 0; y < l.height; ++y)
      for (int x = 0; x < l.width; ++x) {
        char* at = planes.back().data() + (size_t(y) * size_t(l.width) + size_t(x)) * bytes;
        const float v = sample(l, int(c), x, y);
        if (type == Imf::HALF) {
          const Imath::half h(v);
          std::memcpy(at, &h, 2);
        } else if (type == Imf::FLOAT) {
          std::memcpy(at, &v, 4);
        } else {
          const unsigned u = unsigned(v);
          std::memcpy(at, &u, 4);
        }
      }
    fb.insert(l.channels[c].first, Imf::Slice::Make(type, planes.back().data(), dw, bytes, bytes * size_t(l.width)));
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(fb);
  file.writePixels(l.height);
}

// read_exr's frame against readPixels' R, G and B (Y for all three when
// the file has only Y).
void expect_read_exr_is_openexrs(const std::string& path, const std::string& what, const std::string& prefix = "",
                                 const std::string& layer = "") {
  const ExrImage image = read_exr(path, 1 << 24, layer);
  const bool grey = image.channels == "Y";
  for (int c = 0; c < 3; ++c) {
    const std::vector<float> want = test::openexr_channel(path, prefix + (grey ? "Y" : std::string(1, "RGB"[c])));
    size_t differ = 0;
    for (int y = 0; y < image.rgb.rows; ++y)
      for (int x = 0; x < image.rgb.cols; ++x) {
        const float got = image.rgb.at<cv::Vec3f>(y, x)[c];
        const float w = want[size_t(y) * size_t(image.rgb.cols) + size_t(x)];
        differ += std::memcmp(&got, &w, sizeof got) != 0;
      }
    EXPECT_EQ(differ, 0u) << what << ", channel " << c;
  }
}

TEST(ExrChunks, FramesAreOpenExrsOwnSamplesForEveryLayoutItDecodes) {
  test::ScratchDir dir;
  int files = 0;
  for (Imf::Compression compression : {Imf::ZIP_COMPRESSION, Imf::ZIPS_COMPRESSION, Imf::NO_COMPRESSION})
    for (bool noise : {false, true})
      for (int variant = 0; variant < 5; ++variant) {
        Layout l;
        l.compression = compression;
        l.noise = noise;
        std::string what = "compression " + std::to_string(int(compression)) + (noise ? ", noise" : ", smooth");
        if (variant == 1) {  // alpha, depth and an id beside the colour; off the origin
          l.channels = {{"A", Imf::HALF}, {"B", Imf::HALF}, {"G", Imf::HALF}, {"R", Imf::HALF}, {"Z", Imf::FLOAT},
                        {"id", Imf::UINT}};
          l.origin = Imath::V2i(-5, -17);
          what += ", RGBA Z id at (-5, -17)";
        } else if (variant == 2) {  // a whole number of ZIP chunks, lines bottom up
          l.width = 64;
          l.height = 48;
          l.order = Imf::DECREASING_Y;
          what += ", 64x48 decreasing";
        } else if (variant == 3) {  // grey
          l.channels = {{"Y", Imf::HALF}};
          l.height = 1;
          what += ", Y, one line";
        } else if (variant == 4) {  // a layer beside the root's
          l.channels = {{"R", Imf::HALF}, {"G", Imf::HALF}, {"B", Imf::HALF}, {"diffuse.B", Imf::HALF},
                        {"diffuse.G", Imf::HALF}, {"diffuse.R", Imf::HALF}};
          l.width = 1;
          l.height = 33;
          what += ", a diffuse layer, 1x33";
        }
        const std::string path = dir / ("f" + std::to_string(files++) + ".exr");
        write(path, l);
        {
          Imf::InputFile file(path.c_str());
          EXPECT_NE(ExrChunks::open(file, path), nullptr) << what << ": decoded by the program";
        }
        expect_read_exr_is_openexrs(path, what);
        if (variant == 4) expect_read_exr_is_openexrs(path, what + ", diffuse", "diffuse.", "diffuse");
      }
}

TEST(ExrChunks, IncompressibleChunksAreStoredAsTheyAreAndReadSo) {
  // Noise in halves across the whole range: ZIP cannot shrink it, so
  // OpenEXR stores the chunks raw; the smooth file's are deflated.
  test::ScratchDir dir;
  Layout noise;
  noise.noise = true;
  noise.width = 200;
  write(dir / "noise.exr", noise);
  Layout smooth = noise;
  smooth.noise = false;
  write(dir / "smooth.exr", smooth);
  // Each chunk's stored size, as OpenEXR finds it: the noise's all its
  // lines' bytes (stored), the smooth ones' fewer (deflated).
  for (const std::string name : {"noise", "smooth"}) {
    Imf::InputFile file((dir / (name + ".exr")).c_str());
    for (int y = 0; y < noise.height; y += 16) {
      const char* data = nullptr;
      int size = 0;
      file.rawPixelData(y, data, size);
      const int expected = std::min(16, noise.height - y) * noise.width * 6;
      if (name == "noise")
        EXPECT_EQ(size, expected) << "line " << y << ": stored as it is";
      else
        EXPECT_LT(size, expected / 2) << "line " << y << ": deflated";
    }
  }
  expect_read_exr_is_openexrs(dir / "noise.exr", "noise");
  expect_read_exr_is_openexrs(dir / "smooth.exr", "smooth");
}

TEST(ExrChunks, OtherLayoutsAreLeftToOpenExr) {
  test::ScratchDir dir;
  Layout piz;
  piz.compression = Imf::PIZ_COMPRESSION;
  write(dir / "piz.exr", piz);
  Layout floats;
  floats.channels = {{"R", Imf::FLOAT}, {"G", Imf::FLOAT}, {"B", Imf::FLOAT}};
  write(dir / "float.exr", floats);
  {
    Imf::InputFile file((dir / "piz.exr").c_str());
    EXPECT_EQ(ExrChunks::open(file, dir / "piz.exr"), nullptr);
  }
  expect_read_exr_is_openexrs(dir / "piz.exr", "PIZ");
  // Two parts (each chunk of a multi-part file also names its part): the
  // first is read, by OpenEXR.
  {
    Layout part;
    std::vector<Imf::Header> headers;
    for (const char* name : {"left", "right"}) {
      Imf::Header h(part.width, part.height);
      h.compression() = Imf::ZIP_COMPRESSION;
      h.setName(name);
      h.setType(Imf::SCANLINEIMAGE);
      for (const char* c : {"R", "G", "B"}) h.channels().insert(c, Imf::Channel(Imf::HALF));
      headers.push_back(h);
    }
    Imf::MultiPartOutputFile out((dir / "parts.exr").c_str(), headers.data(), int(headers.size()));
    for (int p = 0; p < 2; ++p) {
      std::vector<Imath::half> rgb(size_t(part.width) * size_t(part.height) * 3);
      for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = float(i % 97) * (p + 1.0f);
      Imf::FrameBuffer fb;
      for (int c = 0; c < 3; ++c)
        fb.insert(std::string(1, "RGB"[c]), Imf::Slice(Imf::HALF, reinterpret_cast<char*>(rgb.data() + c), 6,
                                                       6 * size_t(part.width)));
      Imf::OutputPart writer(out, p);
      writer.setFrameBuffer(fb);
      writer.writePixels(part.height);
    }
  }
  {
    Imf::InputFile file((dir / "parts.exr").c_str());
    EXPECT_EQ(ExrChunks::open(file, dir / "parts.exr"), nullptr);
  }
  expect_read_exr_is_openexrs(dir / "parts.exr", "two parts");
  expect_read_exr_is_openexrs(dir / "float.exr", "float");
}

TEST(ExrChunks, ADamagedChunkIsAnInputErrorNamingTheFile) {
  test::ScratchDir dir;
  Layout l;
  l.width = 300;
  l.height = 40;
  const std::string path = dir / "damaged.exr";
  write(path, l);
  std::string bytes = test::read_bytes(path);
  // The last chunk's deflated bytes (the file's tail): overwritten.
  for (size_t i = bytes.size() - 200; i < bytes.size() - 20; ++i) bytes[i] = char(0x5A ^ i);
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  try {
    read_exr(path, 1 << 24);
    ADD_FAILURE() << "read a damaged chunk";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("the chunk at line 32 does not inflate"), std::string::npos)
        << e.what() << ": the program's decoder names the chunk";
  }
}

}  // namespace
}  // namespace eyestream::io
