// The program's own picture codecs (libpng for PNG, its readers of
// Radiance .hdr, PFM and code TIFFs) against OpenCV's image codecs, which
// the program no longer links (io/png_file.hpp) and which serve here as
// the independent oracle: the same PNG bytes as OpenCV's encoder with the
// tags added as the program used to add them, and the same pixels as
// OpenCV's decoders on files OpenCV (or libpng's simplified writer) made.
#include <gtest/gtest.h>
#include <png.h>
#include <tiffio.h>
#include <zlib.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "io/error.hpp"
#include "io/float_image_source.hpp"
#include "io/float_tiff.hpp"
#include "io/pfm_file.hpp"
#include "io/png_file.hpp"
#include "io/radiance_hdr.hpp"
#include "pipeline/eye/target_region.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

// Random codes of `type`, the same for a given seed.
cv::Mat random_codes(int rows, int cols, int type, unsigned seed) {
  cv::Mat m(rows, cols, type);
  cv::RNG rng(seed);
  rng.fill(m, cv::RNG::UNIFORM, 0, CV_MAT_DEPTH(type) == CV_16U ? 65536 : 256);
  return m;
}

void put32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>(v >> shift));
}

// A chunk: length, type, data, then zlib's CRC-32 over type and data.
std::vector<unsigned char> chunk(const char type[4], const std::vector<std::uint32_t>& words) {
  std::vector<unsigned char> c;
  put32(c, std::uint32_t(4 * words.size()));
  c.insert(c.end(), type, type + 4);
  for (std::uint32_t w : words) put32(c, w);
  put32(c, std::uint32_t(crc32(0L, c.data() + 4, uInt(c.size() - 4))));
  return c;
}

// What the program wrote until 2026-12-06: OpenCV's PNG with gAMA and
// cHRM put in after IHDR.
std::vector<unsigned char> opencv_tagged_png(const cv::Mat& m, double gamma) {
  std::vector<unsigned char> png;
  EXPECT_TRUE(cv::imencode(".png", m, png));
  const std::vector<unsigned char> gama = chunk("gAMA", {std::uint32_t(std::lround(gamma * 100000))});
  const std::vector<unsigned char> chrm = chunk("cHRM", {31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000});
  png.insert(png.begin() + 33, chrm.begin(), chrm.end());
  png.insert(png.begin() + 33, gama.begin(), gama.end());
  return png;
}

void write_file(const std::string& path, const std::vector<unsigned char>& bytes) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// OpenCV's decoding of `path` as R, G, B (or grey), alpha dropped.
cv::Mat opencv_rgb(const std::string& path) {
  const cv::Mat m = cv::imread(path, cv::IMREAD_UNCHANGED);
  cv::Mat rgb;
  if (m.channels() == 1) return m;
  cv::cvtColor(m, rgb, m.channels() == 4 ? cv::COLOR_BGRA2RGB : cv::COLOR_BGR2RGB);
  return rgb;
}

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0.0;
}

// Bit for bit, NaN aside (none are written here).
bool same_floats(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return false;
  for (int y = 0; y < a.rows; ++y)
    if (std::memcmp(a.ptr(y), b.ptr(y), a.cols * a.elemSize()) != 0) return false;
  return true;
}

TEST(PictureCodecs, PngBytesAreOpenCvsWithTheTags) {
  int n = 0;
  for (int type : {CV_8UC3, CV_16UC3, CV_8UC1, CV_16UC1})
    for (cv::Size size : {cv::Size(1, 1), cv::Size(37, 5), cv::Size(640, 360)})
      for (double gamma : {1.0 / 2.2, 0.6}) {
        // Smooth rows compress as real frames do; noise tests the stored blocks.
        cv::Mat m = random_codes(size.height, size.width, type, unsigned(++n));
        if (n % 2) cv::GaussianBlur(m, m, cv::Size(9, 9), 3.0);
        EXPECT_EQ(io::encode_png(m, gamma), opencv_tagged_png(m, gamma)) << "type " << type << " " << size;
        std::vector<unsigned char> png = io::encode_png(m, gamma);
        EXPECT_TRUE(same(cv::imdecode(png, cv::IMREAD_UNCHANGED), m));
      }
}

TEST(PictureCodecs, PngReadsAsOpenCvDecodes) {
  test::ScratchDir dir;
  int n = 0;
  for (int type : {CV_8UC1, CV_16UC1, CV_8UC3, CV_16UC3, CV_8UC4, CV_16UC4})
    for (int level : {0, 9}) {
      const std::string path = dir / ("p" + std::to_string(++n) + ".png");
      const cv::Mat m = random_codes(23, 41, type, unsigned(n));
      ASSERT_TRUE(cv::imwrite(path, m, {cv::IMWRITE_PNG_COMPRESSION, level}));
      const cv::Mat got = io::read_png(path);
      EXPECT_TRUE(same(got, opencv_rgb(path))) << "type " << type;
      EXPECT_EQ(got.channels(), type == CV_8UC1 || type == CV_16UC1 ? 1 : 3);
    }
  // One bit a pixel (OpenCV's bilevel writer), a palette with
  // transparency and grey with alpha (libpng's simplified writer), and an
  // interlaced grey one (libpng's full writer).
  const cv::Mat bits = random_codes(19, 29, CV_8UC1, 7) > 127;
  ASSERT_TRUE(cv::imwrite(dir / "bits.png", bits, {cv::IMWRITE_PNG_BILEVEL, 1}));
  EXPECT_TRUE(same(io::read_png(dir / "bits.png"), cv::imread(dir / "bits.png", cv::IMREAD_UNCHANGED)));
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = 29;
  image.height = 19;
  image.format = PNG_FORMAT_RGBA_COLORMAP;
  image.colormap_entries = 3;
  const unsigned char colours[12] = {255, 0, 0, 255, 0, 200, 30, 128, 20, 20, 250, 0};
  cv::Mat indices = random_codes(19, 29, CV_8UC1, 8);
  indices.forEach<unsigned char>([](unsigned char& v, const int*) { v %= 3; });
  ASSERT_TRUE(png_image_write_to_file(&image, (dir / "palette.png").c_str(), 0, indices.data, 29, colours));
  const cv::Mat palette = io::read_png(dir / "palette.png");
  EXPECT_EQ(palette.type(), CV_8UC3);
  EXPECT_TRUE(same(palette, opencv_rgb(dir / "palette.png")));
  png_image ga{};
  ga.version = PNG_IMAGE_VERSION;
  ga.width = 29;
  ga.height = 19;
  ga.format = PNG_FORMAT_GA;
  const cv::Mat grey_alpha = random_codes(19, 29, CV_8UC2, 10);
  ASSERT_TRUE(png_image_write_to_file(&ga, (dir / "ga.png").c_str(), 0, grey_alpha.data, 0, nullptr));
  cv::Mat grey_of_ga;
  cv::extractChannel(grey_alpha, grey_of_ga, 0);
  EXPECT_TRUE(same(io::read_png(dir / "ga.png"), grey_of_ga));
  EXPECT_TRUE(same(cv::imread(dir / "ga.png", cv::IMREAD_GRAYSCALE), grey_of_ga));
  // An Adam7-interlaced file, by libpng's full writer (interlacing is not
  // offered by the simplified one).
  const cv::Mat grey = random_codes(13, 17, CV_8UC1, 9);
  {
    std::FILE* f = std::fopen((dir / "adam7.png").c_str(), "wb");
    ASSERT_NE(f, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, 17, 13, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_ADAM7, PNG_COMPRESSION_TYPE_BASE,
                 PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    std::vector<png_bytep> rows;
    for (int y = 0; y < 13; ++y) rows.push_back(const_cast<png_bytep>(grey.ptr<png_byte>(y)));
    png_write_image(png, rows.data());
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
  }
  EXPECT_TRUE(same(io::read_png(dir / "adam7.png"), grey));
  EXPECT_TRUE(same(cv::imread(dir / "adam7.png", cv::IMREAD_UNCHANGED), grey));
}

TEST(PictureCodecs, DamagedPngIsAnInputErrorNamingTheFile) {
  test::ScratchDir dir;
  const cv::Mat m = random_codes(64, 64, CV_8UC3, 3);
  const std::vector<unsigned char> png = io::encode_png(m);
  write_file(dir / "cut.png", std::vector<unsigned char>(png.begin(), png.begin() + long(png.size() / 2)));
  std::vector<unsigned char> flipped = png;
  flipped[png.size() / 2] ^= 0x40;  // in the image data: its CRC no longer matches
  write_file(dir / "flipped.png", flipped);
  write_file(dir / "text.png", {'n', 'o', 't', ' ', 'a', ' ', 'P', 'N', 'G'});
  for (const char* name : {"cut.png", "flipped.png", "text.png", "missing.png"}) {
    try {
      io::read_png(dir / name);
      ADD_FAILURE() << name << " was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(dir / name), std::string::npos) << e.what();
    }
  }
  try {
    io::read_png(dir / "flipped.png", 100);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("64x64 PNG exceeds the limit of 100 pixels"), std::string::npos) << e.what();
  }
}

// Floats from 1e-6 to 1e6 and zeros: every exponent the format holds there.
cv::Mat random_light(int rows, int cols, int channels, unsigned seed) {
  cv::Mat m(rows, cols, CV_MAKETYPE(CV_32F, channels));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> exponent(-6.0f, 6.0f);
  for (float* p = m.ptr<float>(); p != m.ptr<float>() + m.total() * size_t(channels); ++p)
    *p = rng() % 17 == 0 ? 0.0f : std::pow(10.0f, exponent(rng));
  return m;
}

TEST(PictureCodecs, RadianceHdrReadsAsOpenCvDecodes) {
  test::ScratchDir dir;
  int n = 0;
  // Run-length scanlines (OpenCV writes them for widths 8 to 32767) and
  // flat ones (narrower).
  for (cv::Size size : {cv::Size(3, 2), cv::Size(8, 3), cv::Size(333, 41)}) {
    const std::string path = dir / ("h" + std::to_string(++n) + ".hdr");
    ASSERT_TRUE(cv::imwrite(path, random_light(size.height, size.width, 3, unsigned(n))));
    EXPECT_TRUE(same_floats(io::read_radiance_hdr(path), opencv_rgb(path))) << size;
  }
  // Flat scanlines at a width that could be run-length: random RGBE bytes.
  std::string flat = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 16\n";
  std::mt19937 rng(5);
  for (int i = 0; i < 4 * 16 * 4; ++i) flat += char(i % 4 == 0 && i % 64 == 0 ? 1 : rng() % 256);
  std::ofstream(dir / "flat.hdr", std::ios::binary) << flat;
  EXPECT_TRUE(same_floats(io::read_radiance_hdr(dir / "flat.hdr"), opencv_rgb(dir / "flat.hdr")));
  // A header with CR LF line ends reads the same.
  std::string bytes = test::read_bytes(dir / "h3.hdr");
  const size_t end = bytes.find("\n\n");
  std::string crlf;
  for (size_t i = 0; i < end + 2; ++i) crlf += bytes[i] == '\n' ? std::string("\r\n") : std::string(1, bytes[i]);
  std::ofstream(dir / "crlf.hdr", std::ios::binary) << crlf << bytes.substr(end + 2);
  EXPECT_TRUE(same_floats(io::read_radiance_hdr(dir / "crlf.hdr"), io::read_radiance_hdr(dir / "h3.hdr")));
  // A header as Radiance's own tools and other renderers write it: the
  // program's name, comments, the exposure, gamma, primaries and software
  // lines before the format; read as OpenCV reads it.
  std::ofstream(dir / "renderer.hdr", std::ios::binary)
      << "#?RADIANCE\n# rendered by a test\nSOFTWARE=test 1.0\nEXPOSURE=1.0\nGAMMA=1.0\n"
         "PRIMARIES=0.640 0.330 0.300 0.600 0.150 0.060 0.3127 0.3290\nFORMAT=32-bit_rle_rgbe\n\n"
      << bytes.substr(end + 2);
  EXPECT_TRUE(same_floats(io::read_radiance_hdr(dir / "renderer.hdr"), opencv_rgb(dir / "renderer.hdr")));
  EXPECT_TRUE(same_floats(io::read_radiance_hdr(dir / "renderer.hdr"), io::read_radiance_hdr(dir / "h3.hdr")));
  // Refusals name the file and what is wrong.
  const auto refused = [&](const std::string& name, const std::string& content, const std::string& what) {
    std::ofstream(dir / name, std::ios::binary) << content;
    try {
      io::read_radiance_hdr(dir / name);
      ADD_FAILURE() << name << " was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(dir / name + ": " + what), std::string::npos) << e.what();
    }
  };
  refused("xyz.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n\x80\x80\x80\x81", "holds 32-bit_rle_xyze pixels");
  refused("flipped.hdr", "#?RADIANCE\n\n+Y 1 +X 1\n\x80\x80\x80\x81", "the resolution line");
  refused("short.hdr", bytes.substr(0, bytes.size() - 9), "damaged or short pixel data at scanline 40");
  const std::string head = "#?RADIANCE\n\n-Y 2 +X 8\n";
  refused("long_run.hdr", head + std::string("\x02\x02\x00\x08\x89\x01", 6) + std::string(64, '\x01'),
          "damaged or short pixel data at scanline 0");
  refused("wrong_width.hdr", head + std::string("\x02\x02\x00\x09", 4) + std::string(64, '\x88'),
          "damaged or short pixel data at scanline 0");
  try {
    io::read_radiance_hdr(dir / "h3.hdr", 1000);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("333x41 exceeds the limit of 1000 pixels"), std::string::npos) << e.what();
  }
  // Through the program's still source (its header check first), as a
  // file: the CR LF one reads as the other.
  io::FloatImageSource still(dir / "crlf.hdr", {});
  const std::optional<io::SceneFrame> frame = still.next();
  ASSERT_TRUE(frame.has_value());
  EXPECT_TRUE(same_floats(frame->rgb, io::read_radiance_hdr(dir / "h3.hdr") * 179.0));
}

TEST(PictureCodecs, PfmReadsAsOpenCvDecodes) {
  test::ScratchDir dir;
  for (int channels : {3, 1}) {
    const std::string path = dir / ("f" + std::to_string(channels) + ".pfm");
    ASSERT_TRUE(cv::imwrite(path, random_light(7, 11, channels, unsigned(channels))));
    cv::Mat want = opencv_rgb(path);
    if (channels == 1) cv::cvtColor(want, want, cv::COLOR_GRAY2RGB);
    EXPECT_TRUE(same_floats(io::read_pfm(path), want)) << channels;
  }
  // Big-endian (a positive scale) and a scale other than 1, written here.
  const cv::Mat light = random_light(5, 4, 3, 11);
  std::string file = "PF\n4 5\n3.0\n";
  for (int y = light.rows - 1; y >= 0; --y)
    for (int i = 0; i < light.cols * 3; ++i) {
      std::uint32_t bits;
      std::memcpy(&bits, light.ptr<float>(y) + i, 4);
      for (int shift = 24; shift >= 0; shift -= 8) file += char(bits >> shift);
    }
  std::ofstream(dir / "big.pfm", std::ios::binary) << file;
  EXPECT_TRUE(same_floats(io::read_pfm(dir / "big.pfm"), opencv_rgb(dir / "big.pfm")));
  std::ofstream(dir / "cut.pfm", std::ios::binary) << file.substr(0, file.size() - 4);
  EXPECT_THROW(io::read_pfm(dir / "cut.pfm"), InputError);
  EXPECT_THROW(io::read_pfm(dir / "big.pfm", 19), InputError);  // 20 pixels
  // Big-endian grey.
  std::string grey = "Pf\n4 5\n1.0\n";
  for (int y = light.rows - 1; y >= 0; --y)
    for (int x = 0; x < light.cols; ++x) {
      std::uint32_t bits;
      std::memcpy(&bits, &light.ptr<cv::Vec3f>(y)[x][1], 4);
      for (int shift = 24; shift >= 0; shift -= 8) grey += char(bits >> shift);
    }
  std::ofstream(dir / "grey.pfm", std::ios::binary) << grey;
  cv::Mat want = opencv_rgb(dir / "grey.pfm");
  cv::cvtColor(want, want, cv::COLOR_GRAY2RGB);
  EXPECT_TRUE(same_floats(io::read_pfm(dir / "grey.pfm"), want));
}

// A one-channel TIFF written by libtiff: `bits` a sample (1, 8 or 16),
// `photometric` as given, with a palette when that is PHOTOMETRIC_PALETTE.
void write_tiff(const std::string& path, const cv::Mat& codes, int bits, int photometric) {
  TIFF* t = TIFFOpen(path.c_str(), "w");
  ASSERT_NE(t, nullptr);
  TIFFSetField(t, TIFFTAG_IMAGEWIDTH, std::uint32_t(codes.cols));
  TIFFSetField(t, TIFFTAG_IMAGELENGTH, std::uint32_t(codes.rows));
  TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, std::uint16_t(bits));
  TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, std::uint16_t(1));
  TIFFSetField(t, TIFFTAG_PHOTOMETRIC, std::uint16_t(photometric));
  TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, std::uint32_t(codes.rows));
  std::vector<std::uint16_t> red(256), green(256), blue(256);
  for (int i = 0; i < 256; ++i) red[size_t(i)] = std::uint16_t(i * 257), green[size_t(i)] = std::uint16_t((255 - i) * 257);
  if (photometric == PHOTOMETRIC_PALETTE) TIFFSetField(t, TIFFTAG_COLORMAP, red.data(), green.data(), blue.data());
  for (int y = 0; y < codes.rows; ++y) {
    std::vector<unsigned char> row(size_t(codes.cols) * 2, 0);
    for (int x = 0; x < codes.cols; ++x) {
      const int v = codes.depth() == CV_16U ? codes.at<std::uint16_t>(y, x) : codes.at<unsigned char>(y, x);
      if (bits == 1 && v) row[size_t(x / 8)] |= std::uint8_t(0x80 >> (x % 8));
      if (bits == 8) row[size_t(x)] = std::uint8_t(v);
      if (bits == 16) std::memcpy(&row[size_t(2 * x)], &v, 2);
    }
    ASSERT_EQ(TIFFWriteScanline(t, row.data(), std::uint32_t(y), 0), 1);
  }
  TIFFClose(t);
}

TEST(PictureCodecs, CodeTiffAndMasksReadAsOpenCvDecodes) {
  test::ScratchDir dir;
  for (int type : {CV_8UC3, CV_16UC3, CV_8UC1, CV_16UC1}) {
    const std::string path = dir / ("c" + std::to_string(type) + ".tif");
    ASSERT_TRUE(cv::imwrite(path, random_codes(9, 14, type, unsigned(type))));
    cv::Mat want = opencv_rgb(path);
    if (want.channels() == 1) cv::cvtColor(want, want, cv::COLOR_GRAY2RGB);
    want.convertTo(want, CV_32FC3, CV_MAT_DEPTH(type) == CV_16U ? 1.0 / 65535.0 : 1.0 / 255.0);
    EXPECT_LE(cv::norm(io::read_code_tiff(path, 1000), want, cv::NORM_INF), 1e-7) << type;
  }
  EXPECT_THROW(io::read_code_tiff(dir / ("c" + std::to_string(CV_8UC3) + ".tif"), 125), InputError);  // 126 pixels
  // Palette, white-is-zero and one-bit TIFFs (libtiff's writer), as
  // OpenCV's reader gives their colours.
  const cv::Mat codes = random_codes(11, 21, CV_8UC1, 12);
  write_tiff(dir / "palette.tif", codes, 8, PHOTOMETRIC_PALETTE);
  write_tiff(dir / "white0.tif", codes, 8, PHOTOMETRIC_MINISWHITE);
  write_tiff(dir / "bits.tif", codes > 127, 1, PHOTOMETRIC_MINISWHITE);
  for (const char* name : {"palette.tif", "white0.tif", "bits.tif"}) {
    cv::Mat want = opencv_rgb(dir / name);
    if (want.channels() == 1) cv::cvtColor(want, want, cv::COLOR_GRAY2RGB);
    want.convertTo(want, CV_32FC3, 1.0 / 255.0);
    EXPECT_LE(cv::norm(io::read_code_tiff(dir / name, 1000), want, cv::NORM_INF), 1e-7) << name;
  }
  // A grey PNG mask, a colour one, a colour TIFF, a one-bit TIFF and a
  // 16-bit PNG with codes on both sides of the threshold's high byte: the
  // target is where the grey is above 127, as OpenCV's grey reading gives
  // it (colours kept far from the threshold, where two grey conversions
  // could disagree).
  cv::Mat grey = random_codes(27, 48, CV_8UC1, 5);
  grey.forEach<unsigned char>([](unsigned char& v, const int*) { v = v > 127 ? 240 : 10; });
  ASSERT_TRUE(cv::imwrite(dir / "grey.png", grey));
  cv::Mat colour;
  cv::cvtColor(grey, colour, cv::COLOR_GRAY2BGR);
  ASSERT_TRUE(cv::imwrite(dir / "colour.png", colour));
  ASSERT_TRUE(cv::imwrite(dir / "colour.tif", colour));
  write_tiff(dir / "mask_bits.tif", grey > 127, 1, PHOTOMETRIC_MINISWHITE);
  cv::Mat deep = random_codes(27, 48, CV_16UC1, 6);
  deep.forEach<std::uint16_t>([](std::uint16_t& v, const int*) { v = std::uint16_t(0x7F80 + v % 0x100); });
  ASSERT_TRUE(cv::imwrite(dir / "deep.png", deep));
  for (const char* name : {"grey.png", "colour.png", "colour.tif", "mask_bits.tif", "deep.png"}) {
    const pipeline::TargetRegion target("", dir / name, cv::Size(48, 27));
    EXPECT_TRUE(same(target.mask(0), cv::imread(dir / name, cv::IMREAD_GRAYSCALE) > 127)) << name;
  }
  EXPECT_GT(cv::countNonZero(pipeline::TargetRegion("", dir / "deep.png", cv::Size(48, 27)).mask(0)), 0);
  // Other formats are refused by name.
  std::ofstream(dir / "mask.pgm") << "P5\n48 27\n255\n";
  try {
    pipeline::TargetRegion("", dir / "mask.pgm", cv::Size(48, 27));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mask.pgm: target masks are read from PNG or TIFF files"), std::string::npos)
        << e.what();
  }
}

TEST(PictureCodecs, TheProgramDoesNotLoadOpenCvsImageCodecs) {
  // Structural, not timed: the libraries the dynamic linker loads at
  // every start (docs/performance.md has the time they took).
  std::string loaded;
  FILE* pipe = ::popen(("ldd " + std::string(EYESTREAM_BINARY)).c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) loaded.append(buf, n);
  ASSERT_EQ(::pclose(pipe), 0) << loaded;
  EXPECT_NE(loaded.find("libopencv_core"), std::string::npos) << loaded;
  EXPECT_EQ(loaded.find("libopencv_imgcodecs"), std::string::npos) << loaded;
  EXPECT_EQ(loaded.find("libgdal"), std::string::npos) << loaded;
}

}  // namespace
}  // namespace eyestream
