// Inputs and outputs beyond EXR sequences: raw float frames on standard
// input, video on standard output, Radiance .hdr and PFM stills.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "io/error.hpp"
#include "io/exr_file.hpp"
#include "io/float_image_source.hpp"
#include "io/video_reader.hpp"
#include "io/source_factory.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

constexpr int kW = 48, kH = 32, kFrames = 4;

cv::Mat scene_frame(int k) {
  cv::Mat f = test::constant_frame(kW, kH, cv::Vec3f(20.0f + 5 * k, 20.0f, 15.0f));
  f(cv::Rect(10, 10, 6, 6)).setTo(cv::Scalar(2000, 1500, 1000));
  return f;
}

// The same frames as a raw float stream and as a float EXR sequence give
// the same output, bit for bit.
TEST(StreamInput, RawFramesOnStandardInputMatchTheSameFramesFromFiles) {
  test::ScratchDir dir;
  {
    std::ofstream raw(dir / "frames.raw", std::ios::binary);
    for (int k = 0; k < kFrames; ++k) {
      const cv::Mat f = scene_frame(k);
      raw.write(reinterpret_cast<const char*>(f.data), std::streamsize(f.total() * f.elemSize()));
      char name[32];
      std::snprintf(name, sizeof(name), "/exr/%05d.exr", k);
      std::filesystem::create_directories(dir.path() / "exr");
      io::write_exr(dir.path().string() + name, f, io::ExrWriteOptions{false, std::nullopt, std::nullopt});
    }
  }
  auto r = test::run_eyestream("run -i - --size 48x32 --fps 10 -o " + (dir / "a/%05d.exr") + " < " +
                               (dir / "frames.raw"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = test::run_eyestream("run -i " + (dir / "exr") + " --fps 10 -o " + (dir / "b/%05d.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_EQ(test::count_entries(dir.path() / "a"), kFrames);
  for (int k = 0; k < kFrames; ++k) {
    char name[32];
    std::snprintf(name, sizeof(name), "/%05d.exr", k);
    EXPECT_EQ(test::read_bytes(dir / ("a" + std::string(name))), test::read_bytes(dir / ("b" + std::string(name))))
        << k;
  }
}

TEST(StreamInput, ATruncatedFrameOrAMissingSizeIsRefused) {
  test::ScratchDir dir;
  {
    std::ofstream raw(dir / "short.raw", std::ios::binary);
    const cv::Mat f = scene_frame(0);
    raw.write(reinterpret_cast<const char*>(f.data), std::streamsize(f.total() * f.elemSize()));
    raw.write(reinterpret_cast<const char*>(f.data), 100);
  }
  auto r = test::run_eyestream("run -i - --size 48x32 -o " + (dir / "out.mp4") + " < " + (dir / "short.raw"));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("frame 1 is truncated (100 of 18432 bytes)"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.mp4"));
  // --on-bad-video stop keeps the frames before the cut, as for videos.
  r = test::run_eyestream("run -i - --size 48x32 -o " + (dir / "kept/%05d.png") + " --on-bad-video stop < " +
                          (dir / "short.raw"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("stopping after 1 frames (--on-bad-video stop)"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "kept/00000.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "kept/00001.png"));
  r = test::run_eyestream("run -i - -o " + (dir / "out.mp4") + " < " + (dir / "short.raw"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--size"), std::string::npos) << r.output;
  r = test::run_eyestream("run -i - --size 48by32 -o " + (dir / "out.mp4") + " < " + (dir / "short.raw"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  // A file gives its own size: --size is refused rather than ignored.
  r = test::run_eyestream("run -i " + (dir / "kept/00000.png") + " --size 48x32 -o " + (dir / "o2.mp4"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--size 48x32: only raw frames on standard input"), std::string::npos) << r.output;
}

TEST(StreamOutput, VideoOnStandardOutputIsReadableMatroska) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample flash -o " + (dir / "s") + " --width 64 --height 48 --duration 0.3").exit_code,
            0);
  const std::string command = std::string(EYESTREAM_BINARY) + " run -i " + (dir / "s/frames") +
                              " -o - --format mkv --no-progress > " + (dir / "out.mkv") + " 2> " + (dir / "err.txt");
  ASSERT_EQ(std::system(command.c_str()), 0) << test::read_bytes(dir / "err.txt");
  io::VideoReader reader(dir / "out.mkv");
  int frames = 0;
  while (reader.next()) ++frames;
  EXPECT_EQ(frames, 9);
}

// HEVC (x265, threads fixed by --encoder-threads) and HDR10 bytes do not
// depend on --threads or on the run.
TEST(StreamOutput, HevcAndHdr10BytesAreTheSameWhateverTheThreadCount) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample flash -o " + (dir / "s") + " --width 64 --height 48 --duration 0.3").exit_code,
            0);
  for (const std::string kind : {"--bit-depth 10", "--hdr10 --display-peak 1000"}) {
    std::string bytes[3];
    for (int run = 0; run < 3; ++run) {
      const std::string out = dir / ("v" + std::to_string(run) + ".mkv");
      const auto r = test::run_eyestream("run -y -i " + (dir / "s/frames") + " -o " + out + " " + kind + " --threads " +
                                         (run == 2 ? "2" : "1"));
      ASSERT_EQ(r.exit_code, 0) << r.output;
      bytes[run] = test::read_bytes(out);
    }
    EXPECT_GT(bytes[0].size(), 1000u);
    EXPECT_TRUE(bytes[0] == bytes[1]) << kind << ": two runs";
    EXPECT_TRUE(bytes[0] == bytes[2]) << kind << ": --threads 1 and 2";
  }
}

TEST(StillInput, PfmSequencesAndRadianceFilesAreReadInCandelas) {
  test::ScratchDir dir;
  std::filesystem::create_directories(dir.path() / "pfm");
  for (int k = 0; k < 3; ++k) {
    cv::Mat bgr(kH, kW, CV_32FC3, cv::Scalar(1.0, 2.0, 3.0 + k));  // B, G, R
    char name[32];
    std::snprintf(name, sizeof(name), "/pfm/f%03d.pfm", k + 1);
    ASSERT_TRUE(cv::imwrite(dir.path().string() + name, bgr));
  }
  io::FloatImageSource pfm(dir / "pfm/f%03d.pfm", {});
  EXPECT_EQ(pfm.info().frame_count, 3);
  for (int k = 0; k < 3; ++k) {
    const auto f = pfm.next();
    ASSERT_TRUE(f);
    EXPECT_NEAR(f->time_s, k / 30.0, 1e-12);
    const cv::Vec3f p = f->rgb.at<cv::Vec3f>(5, 5);
    EXPECT_FLOAT_EQ(p[0], 3.0f + k) << "R";
    EXPECT_FLOAT_EQ(p[2], 1.0f) << "B";
  }
  cv::Mat grey(kH, kW, CV_32FC3, cv::Scalar::all(0.5));
  ASSERT_TRUE(cv::imwrite(dir / "still.hdr", grey));
  io::FloatImageSource hdr(dir / "still.hdr", {});
  EXPECT_NEAR(hdr.next()->rgb.at<cv::Vec3f>(3, 3)[1], 0.5 * 179.0, 0.01 * 89.5) << "Radiance: 179 cd/m^2 per unit";
  ASSERT_TRUE(cv::imwrite(dir / "pfm/f004.pfm", cv::Mat(kH + 2, kW, CV_32FC3, cv::Scalar::all(1))));
  io::FloatImageSource changing(dir / "pfm/f%03d.pfm", {});
  for (int k = 0; k < 3; ++k) changing.next();
  EXPECT_THROW(changing.next(), InputError);
  const auto r = test::run_eyestream("run -i " + (dir / "still.hdr") + " -o " + (dir / "still/%05d.png"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST(StillInput, FloatTiffIsReadInCandelasAndItsDeclaredSizeCheckedFirst) {
  // Written by OpenCV's TIFF encoder (libtiff, 32-bit IEEE float), read as
  // a still in cd/m^2, not sent to the video reader.
  test::ScratchDir dir;
  cv::Mat bgr(kH, kW, CV_32FC3, cv::Scalar(0.25, 40.0, 12345.5));  // B, G, R
  ASSERT_TRUE(cv::imwrite(dir / "still.tif", bgr, {cv::IMWRITE_TIFF_COMPRESSION, 1}));  // none: not LogLuv
  const auto source = io::open_source(dir / "still.tif", io::SourceOptions{});
  EXPECT_EQ(source->info().width, kW);
  EXPECT_EQ(source->info().height, kH);
  const cv::Vec3f p = source->next()->rgb.at<cv::Vec3f>(2, 3);
  EXPECT_FLOAT_EQ(p[0], 12345.5f) << "R";
  EXPECT_FLOAT_EQ(p[1], 40.0f) << "G";
  EXPECT_FLOAT_EQ(p[2], 0.25f) << "B";
  // The same reader on a TIFF built byte by byte here (not by OpenCV's
  // writer): 2x2, uncompressed, RGB float32, every pixel (1, 2, 3).
  const std::string seed = test::read_bytes(std::string(EYESTREAM_SOURCE_DIR) + "/fuzz/corpus/float_image/two.tif.bin");
  std::ofstream(dir / "two.tif", std::ios::binary).write(seed.data() + 1, std::streamsize(seed.size() - 1));
  const auto two = io::open_source(dir / "two.tif", io::SourceOptions{});
  EXPECT_EQ(two->info().width, 2);
  const cv::Vec3f q = two->next()->rgb.at<cv::Vec3f>(1, 1);
  EXPECT_EQ(q, cv::Vec3f(1.0f, 2.0f, 3.0f)) << "R, G, B as stored";
  // A classic TIFF header declaring 100000 x 100000: refused before decoding.
  const unsigned char huge[] = {'I', 'I', 42, 0, 8, 0, 0, 0, 2, 0,
                                0, 1, 4, 0, 1, 0, 0, 0, 0xa0, 0x86, 0x01, 0,   // ImageWidth LONG 100000
                                1, 1, 4, 0, 1, 0, 0, 0, 0xa0, 0x86, 0x01, 0,   // ImageLength LONG 100000
                                0, 0, 0, 0};
  std::ofstream(dir / "huge.tiff", std::ios::binary).write(reinterpret_cast<const char*>(huge), sizeof(huge));
  const auto r = test::run_eyestream("run -i " + (dir / "huge.tiff") + " -o " + (dir / "h.mp4"));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("huge.tiff: 100000x100000 exceeds the limit"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace eyestream
