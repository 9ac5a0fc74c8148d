// HDR video input through the FFmpeg libraries: PQ and HLG clips made by
// the project's own writer come back in cd/m^2, BT.2020 is converted with
// out-of-gamut values kept, frame times follow the timestamps, SDR or
// untagged video is refused unless its transfer is stated, and the
// transfer functions invert.
#include <gtest/gtest.h>

#include "io/error.hpp"
#include "io/primaries.hpp"
#include "io/transfer_functions.hpp"
#include "io/video_source.hpp"
#include "io/video_writer.hpp"
#include "pipeline/preview/hdr10_encoding.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

constexpr int kW = 96, kH = 64;

// Writes frames of 16-bit code (or 8-bit) at the given times.
void write_clip(const std::string& path, io::VideoOptions o, const std::vector<cv::Mat>& codes,
                const std::vector<double>& times) {
  o.crf = 4;
  io::VideoWriter writer(path, o);
  for (size_t i = 0; i < codes.size(); ++i) {
    io::DisplayFrame f;
    f.code = codes[i];
    f.index = std::int64_t(i);
    f.time_s = times[i];
    writer.write(f);
  }
  writer.finish();
}

double luminance(const cv::Vec3f& p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

// Two grey patches of luminance a and b (Rec.709 display-linear relative to `peak`).
cv::Mat two_patches(double a, double b, double peak) {
  cv::Mat linear(kH, kW, CV_32FC3, cv::Scalar::all(0.0));
  linear(cv::Rect(0, 0, kW / 2, kH)).setTo(cv::Scalar::all(a / peak));
  linear(cv::Rect(kW / 2, 0, kW / 2, kH)).setTo(cv::Scalar::all(b / peak));
  return linear;
}

TEST(TransferFunctions, InvertAndHitTheirAnchors) {
  EXPECT_NEAR(io::pq_to_luminance(1.0), 10000.0, 1e-6);
  EXPECT_NEAR(io::pq_to_luminance(io::luminance_to_pq(100.0)), 100.0, 1e-9);
  EXPECT_NEAR(io::luminance_to_pq(100.0), 0.5081, 1e-4) << "100 cd/m^2 is PQ 0.508 (BT.2100)";
  EXPECT_NEAR(io::hlg_to_scene(0.5), 1.0 / 12.0, 1e-12);
  EXPECT_NEAR(io::hlg_to_scene(1.0), 1.0, 1e-6);
  EXPECT_NEAR(io::hlg_to_scene(io::scene_to_hlg(0.37)), 0.37, 1e-9);
  EXPECT_DOUBLE_EQ(io::hlg_system_gamma(1000.0), 1.2);
}

TEST(VideoInput, PqHevcPatchesOf5And1000CandelasComeBackWithin1Percent) {
  test::ScratchDir dir;
  io::VideoOptions o;
  o.hdr10 = true;
  cv::Mat code;
  pipeline::encode_hdr10(two_patches(5.0, 1000.0, 1000.0), 1000.0, code);
  write_clip(dir / "pq.mkv", o, {code, code}, {0.0, 1.0 / 30});
  io::VideoSource source(dir / "pq.mkv", {});
  EXPECT_EQ(source.info().width, kW);
  const auto f = source.next();
  ASSERT_TRUE(f);
  EXPECT_NEAR(luminance(f->rgb.at<cv::Vec3f>(kH / 2, kW / 4)), 5.0, 0.05);
  EXPECT_NEAR(luminance(f->rgb.at<cv::Vec3f>(kH / 2, 3 * kW / 4)), 1000.0, 10.0);
}

TEST(VideoInput, HlgIsShownAtItsNominalPeakWithTheSystemGamma) {
  test::ScratchDir dir;
  io::VideoOptions o;
  o.hlg = true;
  cv::Mat code(kH, kW, CV_16UC3);
  code(cv::Rect(0, 0, kW / 2, kH)).setTo(cv::Scalar::all(std::lround(io::scene_to_hlg(0.1) * 65535)));
  code(cv::Rect(kW / 2, 0, kW / 2, kH)).setTo(cv::Scalar::all(std::lround(io::scene_to_hlg(0.5) * 65535)));
  write_clip(dir / "hlg.mp4", o, {code}, {0.0});
  for (double peak : {1000.0, 2000.0}) {
    io::VideoSourceOptions in;
    in.peak_cd_m2 = peak;
    io::VideoSource source(dir / "hlg.mp4", in);
    const auto f = source.next();
    ASSERT_TRUE(f);
    const double gamma = io::hlg_system_gamma(peak);
    // Grey: Y_s = E, so F_D = Lw E^gamma.
    EXPECT_NEAR(luminance(f->rgb.at<cv::Vec3f>(kH / 2, kW / 4)), peak * std::pow(0.1, gamma),
                0.01 * peak * std::pow(0.1, gamma))
        << peak;
    EXPECT_NEAR(luminance(f->rgb.at<cv::Vec3f>(kH / 2, 3 * kW / 4)), peak * std::pow(0.5, gamma),
                0.01 * peak * std::pow(0.5, gamma))
        << peak;
  }
}

TEST(VideoInput, Bt2020GreenIsConvertedWithOutOfGamutValuesKept) {
  test::ScratchDir dir;
  io::VideoOptions o;
  o.hdr10 = true;
  // Rec.709 linear values of BT.2020's pure green at 200 cd/m^2.
  cv::Mat linear(kH, kW, CV_32FC3);
  const cv::Matx33d to709 = io::to_rec709_matrix(io::bt2020_chromaticities());
  const cv::Vec3d g = to709 * cv::Vec3d(0, 200.0 / 0.6780 / 1000.0, 0);  // Y = 0.6780 G in BT.2020
  linear.setTo(cv::Scalar(g[0], g[1], g[2]));
  cv::Mat code;
  pipeline::encode_hdr10(linear, 1000.0, code);
  write_clip(dir / "green.mkv", o, {code}, {0.0});
  io::VideoSource source(dir / "green.mkv", {});
  const cv::Vec3f p = source.next()->rgb.at<cv::Vec3f>(kH / 2, kW / 2);
  EXPECT_LT(p[0], -1.0) << "red goes negative outside Rec.709";
  EXPECT_LT(p[2], -1.0) << "so does blue";
  EXPECT_NEAR(luminance(p), 200.0, 4.0) << "luminance kept";
}

TEST(VideoInput, FrameTimesFollowTheTimestamps) {
  test::ScratchDir dir;
  io::VideoOptions o;
  o.hdr10 = true;
  cv::Mat code(kH, kW, CV_16UC3, cv::Scalar::all(30000));
  write_clip(dir / "vfr.mkv", o, {code, code, code}, {0.0, 2.0 / 30, 5.0 / 30});
  io::VideoSource source(dir / "vfr.mkv", {});
  for (double t : {0.0, 2.0 / 30, 5.0 / 30}) {
    const auto f = source.next();
    ASSERT_TRUE(f);
    EXPECT_NEAR(f->time_s, t, 1e-3);
  }
  EXPECT_FALSE(source.next());
}

TEST(VideoInput, SdrVideoIsRefusedUnlessItsTransferIsStated) {
  test::ScratchDir dir;
  write_clip(dir / "sdr.mp4", io::VideoOptions(), {cv::Mat(kH, kW, CV_8UC3, cv::Scalar::all(128))}, {0.0});
  try {
    io::VideoSource source(dir / "sdr.mp4", {});
    FAIL() << "an SDR video must not be taken for HDR";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sdr.mp4"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("--video-transfer"), std::string::npos);
  }
  io::VideoSourceOptions sdr;
  sdr.transfer = "sdr";
  io::VideoSource source(dir / "sdr.mp4", sdr);
  EXPECT_NEAR(luminance(source.next()->rgb.at<cv::Vec3f>(kH / 2, kW / 2)), 100.0 * std::pow(128 / 255.0, 2.4), 1.0);
  const auto r = test::run_eyestream("run -i " + (dir / "sdr.mp4") + " -o " + (dir / "out.mp4"));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.mp4"));
  const auto ok = test::run_eyestream("run -i " + (dir / "sdr.mp4") + " -o " + (dir / "out.mp4") +
                                      " --video-transfer sdr");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

}  // namespace
}  // namespace eyestream
