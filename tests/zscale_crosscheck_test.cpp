// HDR video luminance against another tool: FFmpeg's command-line program
// with the zscale filter (zimg), when it is installed (Debian's `ffmpeg`;
// the tests skip and say so otherwise).
// - A PQ clip made by zscale from linear light reads as that light.
// - eyestream's HDR10 output, decoded by zscale to linear light, is the
//   light it meant, and its measured content light level (MaxCLL,
//   MaxFALL) is what zscale's decode of the frames gives.
// The expected values are the test's own inputs; zscale (npl=10000: a
// linear 1.0 is 10 000 cd/m^2) does every PQ conversion on its side.
#include <gtest/gtest.h>

extern "C" {
#include <libavformat/avformat.h>
#include <libavutil/mastering_display_metadata.h>
}

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <vector>

#include "io/video_source.hpp"
#include "io/video_writer.hpp"
#include "pipeline/preview/hdr10_encoding.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

constexpr int kW = 64, kH = 32;

std::string shell(const std::string& command) {
  std::string out;
  FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (!p) return out;
  char buf[4096];
  for (size_t n; (n = fread(buf, 1, sizeof(buf), p)) > 0;) out.append(buf, n);
  pclose(p);
  return out;
}

bool have_zscale() {
  static const bool have = shell("ffmpeg -hide_banner -filters").find(" zscale ") != std::string::npos;
  return have;
}

#define SKIP_WITHOUT_ZSCALE() \
  if (!have_zscale()) GTEST_SKIP() << "ffmpeg with zscale is not installed (Debian: apt-get install ffmpeg)"

// Grey patches side by side, left to right, in cd/m^2.
float patch_light(int x, const std::vector<double>& levels) {
  return float(levels[size_t(std::min(x / (kW / int(levels.size())), int(levels.size()) - 1))]);
}

// Planar float G, B, R (ffmpeg's gbrpf32le) of a grey frame, in units of 10 000 cd/m^2.
void write_planar_grey(const std::string& path, const std::vector<double>& levels) {
  std::vector<float> plane(size_t(kW) * kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) plane[size_t(y) * kW + x] = patch_light(x, levels) / 10000.0f;
  std::ofstream out(path, std::ios::binary);
  for (int p = 0; p < 3; ++p) out.write(reinterpret_cast<const char*>(plane.data()), std::streamsize(plane.size() * 4));
}

// Every frame of a video decoded by zscale to linear BT.2020 light, cd/m^2,
// as one CV_32FC3 R, G, B image per frame.
std::vector<cv::Mat> zscale_decode(const std::string& video, const std::string& raw, int w, int h) {
  shell("ffmpeg -v error -y -i '" + video + "' -vf 'zscale=t=linear:npl=10000:p=bt2020,format=gbrpf32le' -f rawvideo '" +
        raw + "'");
  std::ifstream in(raw, std::ios::binary);
  std::vector<cv::Mat> frames;
  std::vector<float> planes(size_t(w) * h * 3);
  while (in.read(reinterpret_cast<char*>(planes.data()), std::streamsize(planes.size() * 4))) {
    cv::Mat rgb(h, w, CV_32FC3);
    const size_t n = size_t(w) * h;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t i = size_t(y) * w + x;  // planes G, B, R
        rgb.at<cv::Vec3f>(y, x) = cv::Vec3f(planes[2 * n + i], planes[i], planes[n + i]) * 10000.0f;
      }
    frames.push_back(rgb);
  }
  return frames;
}

// The content light level in a file's container, read here with libavformat.
bool container_light_level(const std::string& path, unsigned& max_cll, unsigned& max_fall) {
  AVFormatContext* in = nullptr;
  if (avformat_open_input(&in, path.c_str(), nullptr, nullptr) < 0) return false;
  size_t size = 0;
  const uint8_t* data = av_stream_get_side_data(in->streams[0], AV_PKT_DATA_CONTENT_LIGHT_LEVEL, &size);
  const bool ok = data && size >= sizeof(AVContentLightMetadata);
  if (ok) {
    max_cll = reinterpret_cast<const AVContentLightMetadata*>(data)->MaxCLL;
    max_fall = reinterpret_cast<const AVContentLightMetadata*>(data)->MaxFALL;
  }
  avformat_close_input(&in);
  return ok;
}

// CTA-861.3 over decoded frames: the largest of each pixel's largest
// component (MaxCLL) and the largest frame mean of it (MaxFALL), cd/m^2.
std::pair<double, double> light_level_of(const std::vector<cv::Mat>& frames) {
  double cll = 0, fall = 0;
  for (const cv::Mat& f : frames) {
    cv::Mat channels[3];
    cv::split(f, channels);
    const cv::Mat largest = cv::max(cv::max(channels[0], channels[1]), channels[2]);
    double m = 0;
    cv::minMaxLoc(largest, nullptr, &m);
    cll = std::max(cll, m);
    fall = std::max(fall, cv::mean(largest)[0]);
  }
  return {cll, fall};
}

double bt2020_luminance(const cv::Vec3f& p) { return 0.2627 * p[0] + 0.6780 * p[1] + 0.0593 * p[2]; }
double rec709_luminance(const cv::Vec3f& p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

TEST(ZscaleCrossCheck, APqClipMadeByZscaleReadsAsTheLightItHolds) {
  SKIP_WITHOUT_ZSCALE();
  test::ScratchDir dir;
  const std::vector<double> levels = {5.0, 100.0, 1000.0};
  write_planar_grey(dir / "in.raw", levels);
  const std::string log = shell("ffmpeg -v error -y -f rawvideo -pix_fmt gbrpf32le -s " + std::to_string(kW) + "x" +
                                std::to_string(kH) + " -i '" + (dir / "in.raw") +
                                "' -vf 'zscale=tin=linear:t=smpte2084:npl=10000:pin=bt2020:p=bt2020:m=bt2020nc:r=tv,"
                                "format=yuv420p10le' -color_primaries bt2020 -color_trc smpte2084 -colorspace bt2020nc "
                                "-color_range tv -c:v ffv1 '" + (dir / "pq.mkv") + "'");
  io::VideoSource source(dir / "pq.mkv", {});
  const auto frame = source.next();
  ASSERT_TRUE(frame) << log;
  for (size_t i = 0; i < levels.size(); ++i) {
    const int x = int(i) * (kW / 3) + kW / 6;
    const double got = rec709_luminance(frame->rgb.at<cv::Vec3f>(kH / 2, x));
    EXPECT_NEAR(got / levels[i], 1.0, 0.007) << levels[i] << " cd/m^2 read as " << got;
  }
}

TEST(ZscaleCrossCheck, Hdr10OutputDecodedByZscaleIsTheLightItMeantWithItsMeasuredLightLevel) {
  SKIP_WITHOUT_ZSCALE();
  test::ScratchDir dir;
  const double peak = 1000.0;
  io::VideoOptions o;
  o.hdr10 = true;
  o.crf = 0;
  o.frames_per_second = 30;
  // Two frames: grey patches, then a 300 cd/m^2 field with an 8x8 800 cd/m^2 lamp.
  const std::vector<double> levels = {5.0, 100.0, 1000.0};
  cv::Mat first(kH, kW, CV_32FC3), second(kH, kW, CV_32FC3, cv::Scalar::all(300.0 / peak));
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) first.at<cv::Vec3f>(y, x) = cv::Vec3f::all(float(patch_light(x, levels) / peak));
  second(cv::Rect(28, 12, 8, 8)).setTo(cv::Scalar::all(800.0 / peak));
  const std::string path = dir / "out.mp4";
  {
    io::VideoWriter writer(path, o);
    for (const cv::Mat* linear : {&first, &second}) {
      io::DisplayFrame f;
      pipeline::encode_hdr10(*linear, peak, f.code);
      writer.write(f);
    }
    writer.finish();
  }
  const std::vector<cv::Mat> decoded = zscale_decode(path, dir / "out.raw", kW, kH);
  ASSERT_EQ(decoded.size(), 2u);
  for (size_t i = 0; i < levels.size(); ++i) {
    const int x = int(i) * (kW / 3) + kW / 6;
    const double got = bt2020_luminance(decoded[0].at<cv::Vec3f>(kH / 2, x));
    EXPECT_NEAR(got / levels[i], 1.0, 0.007) << levels[i] << " cd/m^2 decoded by zscale as " << got;
  }
  const cv::Scalar lamp = cv::mean(decoded[1](cv::Rect(30, 14, 4, 4)));
  EXPECT_NEAR(bt2020_luminance(cv::Vec3f(float(lamp[0]), float(lamp[1]), float(lamp[2]))) / 800.0, 1.0, 0.007)
      << "the lamp's middle";

  // CTA-861.3: MaxCLL the brightest pixel's largest component (the 1000
  // cd/m^2 patch), MaxFALL the largest frame mean of it (the second frame).
  unsigned max_cll = 0, max_fall = 0;
  ASSERT_TRUE(container_light_level(path, max_cll, max_fall)) << "no content light level in the MP4";
  double first_mean = 0;
  for (int x = 0; x < kW; ++x) first_mean += patch_light(x, levels) / kW;
  const double fall = std::max(first_mean, (300.0 * (kW * kH - 64) + 800.0 * 64) / (kW * kH));
  EXPECT_NEAR(max_cll, 1000.0, 1.0);
  EXPECT_NEAR(max_fall, fall, 1.0);
  const auto [decoded_cll, decoded_fall] = light_level_of(decoded);
  // The decoded frames carry the codec's error (x265 at CRF 0 is not lossless).
  EXPECT_NEAR(max_cll / decoded_cll, 1.0, 0.03) << "zscale's frames give MaxCLL " << decoded_cll;
  EXPECT_NEAR(max_fall / decoded_fall, 1.0, 0.01) << "zscale's frames give MaxFALL " << decoded_fall;
}

// The command line end to end: a night drive in HDR10, its measured light
// level against the frames zscale decodes.
TEST(ZscaleCrossCheck, TheCommandLinesHdr10LightLevelIsTheDecodedFrames) {
  SKIP_WITHOUT_ZSCALE();
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample night-drive -o " + (dir / "nd") + " --width 160 --height 90 --duration 0.5")
                .exit_code,
            0);
  const auto r = test::run_eyestream("run -i " + (dir / "nd/frames") + " -g " + (dir / "nd/gaze.csv") + " -o " +
                                     (dir / "hdr.mp4") + " --hdr10 --display-peak 1000 --crf 0");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  unsigned max_cll = 0, max_fall = 0;
  ASSERT_TRUE(container_light_level(dir / "hdr.mp4", max_cll, max_fall));
  const auto [decoded_cll, decoded_fall] = light_level_of(zscale_decode(dir / "hdr.mp4", dir / "hdr.raw", 160, 90));
  ASSERT_GT(decoded_fall, 0.0);
  std::printf("MaxCLL %u (zscale's frames %.1f), MaxFALL %u (%.2f)\n", max_cll, decoded_cll, max_fall, decoded_fall);
  EXPECT_NEAR(max_fall / decoded_fall, 1.0, 0.03);
  EXPECT_NEAR(max_cll / decoded_cll, 1.0, 0.10) << "4:2:0 chroma moves a small lamp's largest component";
}

}  // namespace
}  // namespace eyestream
