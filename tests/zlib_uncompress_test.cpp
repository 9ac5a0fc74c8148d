// The program's `uncompress` (io/zlib_uncompress.cpp: libdeflate behind
// zlib's one-call interface, for OpenEXR's ZIP blocks) against zlib's own,
// found past the program with dlsym(RTLD_NEXT): the same bytes and length
// for every stream zlib's `compress2` makes, the same verdicts on buffers
// too small, corrupt or cut short. And OpenEXR, bound to it, reads a ZIP
// frame as the same floats as the uncompressed file.
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfCompression.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <random>
#include <vector>

namespace eyestream {
namespace {

using Uncompress = int (*)(Bytef*, uLongf*, const Bytef*, uLong);

Uncompress zlibs_own() {
  static const auto f = reinterpret_cast<Uncompress>(dlsym(RTLD_NEXT, "uncompress"));
  return f;
}

std::vector<Bytef> compressed(const std::vector<Bytef>& data, int level) {
  uLongf n = compressBound(uLong(data.size()));
  std::vector<Bytef> out(n);
  EXPECT_EQ(compress2(out.data(), &n, data.data(), uLong(data.size()), level), Z_OK);
  out.resize(n);
  return out;
}

// Runs both on `in` with `room` bytes of output; they must agree: on
// success the same bytes and count, on failure a failure, and (where
// `same_code`) the same code. zlib's codes for a stream of a byte or two
// cut short differ (Z_BUF_ERROR where a longer one gives Z_DATA_ERROR);
// OpenEXR treats every code but Z_OK and Z_MEM_ERROR alike.
void expect_same(const std::vector<Bytef>& in, size_t room, const std::string& what, bool same_code = true) {
  std::vector<Bytef> ours(room + 1, 0xAB), theirs(room + 1, 0xAB);
  uLongf n_ours = uLongf(room), n_theirs = uLongf(room);
  const int r_ours = uncompress(ours.data(), &n_ours, in.data(), uLong(in.size()));
  const int r_theirs = zlibs_own()(theirs.data(), &n_theirs, in.data(), uLong(in.size()));
  ASSERT_EQ(r_ours == Z_OK, r_theirs == Z_OK) << what << ": ours " << r_ours << ", zlib's " << r_theirs;
  if (r_theirs == Z_OK) {
    ASSERT_EQ(n_ours, n_theirs) << what;
    EXPECT_TRUE(std::equal(ours.begin(), ours.begin() + long(n_ours), theirs.begin())) << what;
    EXPECT_EQ(ours[room], 0xAB) << what << ": wrote past the buffer";
  } else if (same_code) {
    EXPECT_EQ(r_ours, r_theirs) << what;
  }
}

TEST(ZlibUncompress, TheProgramsOwnIsTheOneBoundAndZlibsIsBehindIt) {
  ASSERT_NE(zlibs_own(), nullptr);
  EXPECT_NE(zlibs_own(), &uncompress) << "dlsym(RTLD_NEXT) found the program's own again";
  // What a library's unversioned reference binds to: the first definition
  // in the global scope, the program's (exported by CMakeLists.txt).
  EXPECT_EQ(reinterpret_cast<Uncompress>(dlsym(RTLD_DEFAULT, "uncompress")), &uncompress);
}

TEST(ZlibUncompress, AgreesWithZlibOnEveryStreamAndEveryFault) {
  std::mt19937 rng(7);
  for (size_t size : {size_t(0), size_t(1), size_t(100), size_t(65536), size_t(1) << 20}) {
    // Half floats of a smooth image with noise: ZIP's kind of data, and
    // random bytes, which do not compress.
    std::vector<Bytef> smooth(size), noise(size);
    for (size_t i = 0; i < size; ++i) {
      smooth[i] = Bytef((i / 7) % 251 + (rng() % 3));
      noise[i] = Bytef(rng());
    }
    for (const std::vector<Bytef>* data : {&smooth, &noise})
      for (int level : {1, 6, 9}) {
        const std::vector<Bytef> z = compressed(*data, level);
        const std::string of = " (" + std::to_string(data->size()) + " bytes, level " + std::to_string(level) + ")";
        expect_same(z, data->size(), "exact room" + of);
        expect_same(z, data->size() + 100, "more room" + of);
        // With no room at all zlib inflates into a byte of its own and says
        // Z_OK for a one-byte stream, the byte lost: not compared.
        if (data->size() > 1) expect_same(z, data->size() - 1, "a byte short" + of);
        if (z.size() > 8) {
          std::vector<Bytef> cut(z.begin(), z.begin() + long(z.size() / 2));
          expect_same(cut, data->size(), "cut in half" + of, data->size() > 1);
          std::vector<Bytef> bad = z;
          bad[0] ^= 0x40;  // the header's window size: its check bits fail
          expect_same(bad, data->size(), "bad header" + of);
          std::vector<Bytef> flipped = z;
          flipped[z.size() - 1] ^= 0x01;  // the Adler-32 check
          expect_same(flipped, data->size(), "bad checksum" + of);
          std::vector<Bytef> trailing = z;
          trailing.insert(trailing.end(), {1, 2, 3});
          expect_same(trailing, data->size(), "bytes after the stream" + of);
        }
      }
  }
}

// A 83-row RGB half image written with ZIP and without compression: the
// floats OpenEXR reads back are the same (ZIP through the program's
// uncompress).
TEST(ZlibUncompress, OpenExrReadsAZipFrameAsTheUncompressedOne) {
  const int w = 97, h = 83;
  std::vector<Imath::half> pixels(size_t(w) * h * 3);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = Imath::half(float(std::sin(0.01 * double(i)) * 1000.0));
  const auto dir = std::filesystem::temp_directory_path() / "eyestream_zlib_uncompress_test";
  std::filesystem::create_directories(dir);
  std::vector<std::vector<float>> read;
  for (Imf::Compression c : {Imf::NO_COMPRESSION, Imf::ZIP_COMPRESSION, Imf::ZIPS_COMPRESSION}) {
    const std::string path = (dir / ("frame" + std::to_string(int(c)) + ".exr")).string();
    {
      Imf::Header header(w, h);
      header.compression() = c;
      Imf::FrameBuffer fb;
      const char* names[3] = {"R", "G", "B"};
      for (int k = 0; k < 3; ++k) {
        header.channels().insert(names[k], Imf::Channel(Imf::HALF));
        fb.insert(names[k], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(pixels.data() + k), 3 * sizeof(Imath::half),
                                       3 * sizeof(Imath::half) * size_t(w)));
      }
      Imf::OutputFile out(path.c_str(), header);
      out.setFrameBuffer(fb);
      out.writePixels(h);
    }
    std::vector<float> values(size_t(w) * h * 3, -1.0f);
    Imf::InputFile in(path.c_str());
    Imf::FrameBuffer fb;
    const char* names[3] = {"R", "G", "B"};
    for (int k = 0; k < 3; ++k)
      fb.insert(names[k], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data() + k), 3 * sizeof(float),
                                     3 * sizeof(float) * size_t(w)));
    in.setFrameBuffer(fb);
    in.readPixels(0, h - 1);
    read.push_back(values);
  }
  std::filesystem::remove_all(dir);
  EXPECT_EQ(read[1], read[0]) << "ZIP";
  EXPECT_EQ(read[2], read[0]) << "ZIPS";
  EXPECT_EQ(read[0][5], float(pixels[5]));
}

}  // namespace
}  // namespace eyestream
