#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfCompression.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "io/error.hpp"
#include "io/exr_file.hpp"
#include "io/exr_sequence_source.hpp"
#include "tests/test_support.hpp"

namespace eyestream::io {
namespace {

using test::ScratchDir;

cv::Mat ramp(int w, int h) {
  cv::Mat m(h, w, CV_32FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.at<cv::Vec3f>(y, x) = cv::Vec3f(0.001f * (x + 1), 10.0f * (y + 1), 500.0f + x * y);
  return m;
}

// Writes a file with only the given channels (float), for layouts the
// project's writer does not produce.
void write_channels(const std::string& path, const cv::Mat& rgb, const std::vector<std::string>& names,
                    const std::optional<Imf::Chromaticities>& chroma = std::nullopt) {
  Imf::Header header(rgb.cols, rgb.rows);
  for (const std::string& n : names) header.channels().insert(n, Imf::Channel(Imf::FLOAT));
  if (chroma) Imf::addChromaticities(header, *chroma);
  Imf::OutputFile file(path.c_str(), header);
  Imf::FrameBuffer fb;
  char* base = const_cast<char*>(reinterpret_cast<const char*>(rgb.ptr<float>()));
  const size_t xs = 3 * sizeof(float), ys = xs * size_t(rgb.cols);
  for (size_t i = 0; i < names.size(); ++i)
    fb.insert(names[i], Imf::Slice(Imf::FLOAT, base + (i % 3) * sizeof(float), xs, ys));
  file.setFrameBuffer(fb);
  file.writePixels(rgb.rows);
}

TEST(ExrFile, FloatRoundTripIsExactAndKeepsAttributes) {
  ScratchDir dir;
  const cv::Mat in = ramp(17, 9);
  write_exr(dir / "a.exr", in, {false, 250.0, 24.0});
  const ExrImage out = read_exr(dir / "a.exr", 1 << 20);
  EXPECT_EQ(cv::norm(in, out.rgb, cv::NORM_INF), 0.0);
  ASSERT_TRUE(out.white_luminance);
  EXPECT_DOUBLE_EQ(*out.white_luminance, 250.0);
  ASSERT_TRUE(out.frames_per_second);
  EXPECT_NEAR(*out.frames_per_second, 24.0, 1e-9);
  EXPECT_EQ(out.channels, "RGB");
}

TEST(ExrFile, HalfRoundTripIsWithinHalfPrecision) {
  ScratchDir dir;
  const cv::Mat in = ramp(8, 8);
  write_exr(dir / "h.exr", in, {true, std::nullopt, std::nullopt});
  const ExrImage out = read_exr(dir / "h.exr", 1 << 20);
  cv::Mat rel;
  cv::divide(cv::abs(out.rgb - in), in, rel);
  EXPECT_LT(cv::norm(rel, cv::NORM_INF), 1.0 / 1024);
  EXPECT_FALSE(out.white_luminance);
}

TEST(ExrFile, LuminanceOnlyFilesBecomeGreyRgb) {
  ScratchDir dir;
  const cv::Mat in = ramp(5, 4);
  write_channels(dir / "y.exr", in, {"Y"});
  const ExrImage out = read_exr(dir / "y.exr", 1 << 20);
  EXPECT_EQ(out.channels, "Y");
  const cv::Vec3f p = out.rgb.at<cv::Vec3f>(2, 3);
  EXPECT_EQ(p[0], in.at<cv::Vec3f>(2, 3)[0]);
  EXPECT_EQ(p[1], p[0]);
  EXPECT_EQ(p[2], p[0]);
}

TEST(ExrFile, RgbaFilesReadTheirColourChannels) {
  ScratchDir dir;
  const cv::Mat in = ramp(6, 3);
  write_channels(dir / "rgba.exr", in, {"R", "G", "B", "A"});
  const ExrImage out = read_exr(dir / "rgba.exr", 1 << 20);
  EXPECT_EQ(out.channels, "RGBA");
  EXPECT_EQ(cv::norm(in, out.rgb, cv::NORM_INF), 0.0);
}

TEST(ExrFile, OversizedHeaderIsRefusedBeforeReading) {
  ScratchDir dir;
  write_exr(dir / "big.exr", ramp(64, 64), {false, std::nullopt, std::nullopt});
  try {
    read_exr(dir / "big.exr", 1000);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("big.exr"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("--max-pixels"), std::string::npos);
  }
}

TEST(ExrFile, TruncatedFileIsAnInputErrorNamingIt) {
  ScratchDir dir;
  write_exr(dir / "t.exr", ramp(64, 64), {false, std::nullopt, std::nullopt});
  std::string bytes = test::read_bytes(dir / "t.exr");
  std::ofstream(dir / "t.exr", std::ios::binary | std::ios::trunc)
      .write(bytes.data(), std::streamsize(bytes.size() / 2));
  EXPECT_THROW(read_exr(dir / "t.exr", 1 << 20), InputError);
}

TEST(ExrSequenceSource, WhiteLuminanceScalesToCandelasAndScaleOverrides) {
  ScratchDir dir;
  write_exr(dir / "f_0001.exr", test::constant_frame(4, 4, {1, 1, 1}), {false, 300.0, 25.0});
  {
    ExrSequenceSource source(dir / "f_%04d.exr", ExrSequenceOptions{});
    EXPECT_DOUBLE_EQ(source.info().frames_per_second, 25.0);
    EXPECT_FLOAT_EQ(source.next()->rgb.at<cv::Vec3f>(0, 0)[1], 300.0f);
  }
  ExrSequenceOptions o;
  o.scale = 2.0;
  o.frames_per_second = 50.0;
  ExrSequenceSource source(dir / "f_%04d.exr", o);
  EXPECT_DOUBLE_EQ(source.info().frames_per_second, 50.0);
  EXPECT_FLOAT_EQ(source.next()->rgb.at<cv::Vec3f>(0, 0)[1], 2.0f);
}

TEST(ExrSequenceSource, OtherPrimariesAreConvertedToRec709) {
  ScratchDir dir;
  // BT.2020 pure green is outside Rec.709: it must come back with a negative
  // channel (kept, not clipped) and the same luminance.
  const Imf::Chromaticities bt2020(Imath::V2f(0.708f, 0.292f), Imath::V2f(0.170f, 0.797f), Imath::V2f(0.131f, 0.046f),
                                   Imath::V2f(0.3127f, 0.3290f));
  write_channels(dir / "g.exr", test::constant_frame(2, 2, {0, 1, 0}), {"R", "G", "B"}, bt2020);
  write_channels(dir / "w.exr", test::constant_frame(2, 2, {1, 1, 1}), {"R", "G", "B"}, bt2020);
  const cv::Vec3f g = ExrSequenceSource(dir / "g.exr", {}).next()->rgb.at<cv::Vec3f>(0, 0);
  const cv::Vec3f w = ExrSequenceSource(dir / "w.exr", {}).next()->rgb.at<cv::Vec3f>(0, 0);
  EXPECT_LT(g[0], 0.0f);
  EXPECT_LT(g[2], 0.0f);
  EXPECT_NEAR(0.2126 * g[0] + 0.7152 * g[1] + 0.0722 * g[2], 0.6780, 2e-3);  // BT.2020 green's luminance
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(w[c], 1.0f, 1e-5f);
}

TEST(ExrSequenceSource, FrameOfAnotherSizeIsAnInputErrorNamingIt) {
  ScratchDir dir;
  write_exr(dir / "s_00.exr", test::constant_frame(4, 4, {1, 1, 1}), {true, std::nullopt, std::nullopt});
  write_exr(dir / "s_01.exr", test::constant_frame(5, 4, {1, 1, 1}), {true, std::nullopt, std::nullopt});
  ExrSequenceSource source(dir / "s_%02d.exr", {});
  ASSERT_TRUE(source.next());
  try {
    source.next();
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s_01.exr"), std::string::npos);
  }
}

TEST(ExrSequenceSource, FrameWithOtherChannelsIsAnInputErrorNamingIt) {
  ScratchDir dir;
  write_channels(dir / "c_00.exr", test::constant_frame(4, 4, {1, 1, 1}), {"R", "G", "B"});
  write_channels(dir / "c_01.exr", test::constant_frame(4, 4, {1, 1, 1}), {"Y"});
  ExrSequenceSource source(dir / "c_%02d.exr", {});
  ASSERT_TRUE(source.next());
  try {
    source.next();
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c_01.exr: frame 1 has channels Y, the sequence began with RGB"),
              std::string::npos)
        << e.what();
  }
}

// A float RGB file in the given compression, with a white luminance.
void write_compressed(const std::string& path, const cv::Mat& rgb, Imf::Compression compression, float white,
                      const std::optional<Imf::Chromaticities>& chroma = std::nullopt) {
  Imf::Header header(rgb.cols, rgb.rows);
  header.compression() = compression;
  if (chroma) Imf::addChromaticities(header, *chroma);
  for (const char* n : {"R", "G", "B"}) header.channels().insert(n, Imf::Channel(Imf::FLOAT));
  Imf::addWhiteLuminance(header, white);
  Imf::OutputFile file(path.c_str(), header);
  Imf::FrameBuffer fb;
  char* base = const_cast<char*>(reinterpret_cast<const char*>(rgb.ptr<float>()));
  const size_t xs = 3 * sizeof(float), ys = xs * size_t(rgb.cols);
  for (int c = 0; c < 3; ++c) fb.insert(std::string(1, "RGB"[c]), Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xs, ys));
  file.setFrameBuffer(fb);
  file.writePixels(rgb.rows);
}

TEST(ExrSequenceSource, EveryBandIsScaledOnceAndItsNonFinitePixelsCounted) {
  // The source reads a file in bands of whole line buffers (1, 16 or 32
  // lines by compression), scales each and counts its non-finite pixels
  // while it is in cache. 83 rows: no compression's band divides them.
  // Placed: NaN and infinities at band edges (rows 0, 15, 16, 31, 32, 82),
  // one pixel with two bad channels (counted once), and a finite value that
  // the white luminance takes beyond float's range (counted: it is infinite
  // in candelas): 8 pixels.
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  cv::Mat in = ramp(13, 83);
  in.at<cv::Vec3f>(0, 0)[0] = nan;
  in.at<cv::Vec3f>(15, 12)[1] = inf;
  in.at<cv::Vec3f>(16, 3)[2] = -inf;
  in.at<cv::Vec3f>(31, 7) = cv::Vec3f(nan, inf, 1.0f);
  in.at<cv::Vec3f>(32, 0)[1] = nan;
  in.at<cv::Vec3f>(82, 12)[2] = nan;
  in.at<cv::Vec3f>(50, 5)[0] = 3e38f;
  in.at<cv::Vec3f>(81, 1)[2] = -inf;
  const float white = 10.0f;
  for (Imf::Compression c : {Imf::NO_COMPRESSION, Imf::ZIP_COMPRESSION, Imf::PIZ_COMPRESSION}) {
    SCOPED_TRACE(int(c));
    ScratchDir dir;
    write_compressed(dir / "n.exr", in, c, white);
    const std::optional<SceneFrame> f = ExrSequenceSource(dir / "n.exr", {}).next();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->nonfinite, 8);
    // Every other value is the file's times the white luminance, once.
    int compared = 0;
    for (int y = 0; y < in.rows; ++y)
      for (int x = 0; x < in.cols; ++x)
        for (int k = 0; k < 3; ++k) {
          const float v = in.at<cv::Vec3f>(y, x)[k];
          if (!std::isfinite(v) || std::abs(v) > 1e37f) continue;
          ASSERT_EQ(f->rgb.at<cv::Vec3f>(y, x)[k], v * white) << y << " " << x << " " << k;
          ++compared;
        }
    EXPECT_GT(compared, 3200);
  }
}

TEST(ExrSequenceSource, OtherPrimariesGiveTheBytesOfOneTransformOfTheWholeImage) {
  // cv::transform rounds its vector and scalar paths differently: a file in
  // other primaries goes through the matrix as one image (as before the
  // banded reading), not band by band, so its bytes do not depend on the
  // compression's block height.
  const Imf::Chromaticities bt2020(Imath::V2f(0.708f, 0.292f), Imath::V2f(0.170f, 0.797f), Imath::V2f(0.131f, 0.046f),
                                   Imath::V2f(0.3127f, 0.3290f));
  const cv::Mat in = ramp(13, 83);
  for (Imf::Compression c : {Imf::NO_COMPRESSION, Imf::ZIP_COMPRESSION, Imf::PIZ_COMPRESSION}) {
    SCOPED_TRACE(int(c));
    ScratchDir dir;
    write_compressed(dir / "p.exr", in, c, 4.0f, bt2020);
    // The primaries as the file holds them (floats), through one call.
    const ExrImage raw = read_exr(dir / "p.exr", 1 << 20);
    ASSERT_TRUE(raw.chromaticities);
    cv::Mat expected = in.clone();
    apply_matrix(expected, to_rec709_matrix(*raw.chromaticities));
    expected *= 4.0;
    const std::optional<SceneFrame> f = ExrSequenceSource(dir / "p.exr", {}).next();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->nonfinite, 0);
    EXPECT_EQ(cv::norm(f->rgb, expected, cv::NORM_INF), 0.0);
  }
}

}  // namespace
}  // namespace eyestream::io
