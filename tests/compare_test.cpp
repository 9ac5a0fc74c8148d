// `eyestream compare`: exit codes 0/1/2 on identical, slightly and very
// changed sequences, mismatches as failures, the JSON report and the
// difference images; and the video reader it uses.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "io/video_reader.hpp"
#include "io/video_writer.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

// `frames` PNGs of 64x48 in DIR/name/, grey `level` plus a coloured patch,
// with `delta` added to every code value.
std::string write_sequence(const test::ScratchDir& dir, const std::string& name, int frames, int delta,
                           cv::Size size = cv::Size(64, 48), int first = 0) {
  std::filesystem::create_directories(dir.path() / name);
  for (int i = 0; i < frames; ++i) {
    cv::Mat img(size, CV_8UC3, cv::Scalar(120 + i, 128, 136));
    img(cv::Rect(8, 8, 16, 16)).setTo(cv::Scalar(40, 90, 200));
    img += cv::Scalar::all(delta);
    char file[32];
    std::snprintf(file, sizeof(file), "/%05d.png", first + i);
    cv::imwrite((dir.path() / name).string() + file, img);
  }
  return dir / (name + "/%05d.png");
}

TEST(Compare, ExitCodesPassWarnFailOnIdenticalSlightAndLargeChanges) {
  test::ScratchDir dir;
  const std::string a = write_sequence(dir, "a", 3, 0), same = write_sequence(dir, "same", 3, 0);
  const std::string slight = write_sequence(dir, "slight", 3, 2), large = write_sequence(dir, "large", 3, 40);
  const std::string judge = " --metric max --warn 0.001 --fail 0.05";
  auto r = test::run_eyestream("compare " + a + " " + same + judge);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("pass"), std::string::npos);
  r = test::run_eyestream("compare " + a + " " + slight + judge);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  r = test::run_eyestream("compare " + a + " " + large + judge);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  // The default judges p99 CIEDE2000: 2 code values are below 1, 40 far above.
  EXPECT_EQ(test::run_eyestream("compare " + a + " " + same).exit_code, 0);
  EXPECT_EQ(test::run_eyestream("compare " + a + " " + large).exit_code, 2);
  r = test::run_eyestream("compare " + a + " " + slight + " --metric de99 --warn 100 --fail 100");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST(Compare, ByDefaultAVisibleLocalChangeFailsAndDitherSizedNoisePasses) {
  // As idiff judges a regression: a 10x10 white square pasted into every
  // frame fails however small a share of the frame it is; +-1 code of
  // random noise on every pixel (the size of dithering) passes.
  test::ScratchDir dir;
  const std::string a = write_sequence(dir, "a", 3, 0, cv::Size(320, 240));
  std::filesystem::create_directories(dir.path() / "square");
  std::filesystem::create_directories(dir.path() / "noise");
  cv::RNG rng(5);
  for (int i = 0; i < 3; ++i) {
    char file[32];
    std::snprintf(file, sizeof(file), "/%05d.png", i);
    cv::Mat img = cv::imread((dir.path() / "a").string() + file);
    cv::Mat square = img.clone();
    square(cv::Rect(200, 100, 10, 10)).setTo(cv::Scalar::all(255));
    cv::imwrite((dir.path() / "square").string() + file, square);
    cv::Mat noise(img.size(), CV_16SC3);
    rng.fill(noise, cv::RNG::UNIFORM, -1, 2);  // -1, 0 or +1
    cv::Mat noisy;
    img.convertTo(noisy, CV_16SC3);
    noisy += noise;
    noisy.convertTo(noisy, CV_8UC3);
    cv::imwrite((dir.path() / "noise").string() + file, noisy);
  }
  auto r = test::run_eyestream("compare " + a + " " + (dir / "square/%05d.png"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("largest CIEDE2000"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("00000.png, x 20"), std::string::npos) << "names the frame and the pixel: " << r.output;
  r = test::run_eyestream("compare " + a + " " + (dir / "noise/%05d.png"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST(Compare, MismatchedCountsOrSizesFailWithAMessage) {
  test::ScratchDir dir;
  const std::string a = write_sequence(dir, "a", 3, 0), shorter = write_sequence(dir, "short", 2, 0);
  const std::string wide = write_sequence(dir, "wide", 3, 0, cv::Size(80, 48));
  auto r = test::run_eyestream("compare " + a + " " + shorter);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("A has 3 frames, B 2"), std::string::npos) << r.output;
  r = test::run_eyestream("compare " + a + " " + wide);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("64x48"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("80x48"), std::string::npos) << r.output;
  r = test::run_eyestream("compare " + a + " " + (dir / "missing.mp4"));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("missing.mp4"), std::string::npos) << r.output;
}

TEST(Compare, WritesAJsonReportAndOneDifferenceImagePerFrame) {
  test::ScratchDir dir;
  const std::string a = write_sequence(dir, "a", 3, 0), b = write_sequence(dir, "b", 3, 2);
  const auto r = test::run_eyestream("compare " + a + " " + b + " --json " + (dir / "r.json") + " --diff-out " +
                                     (dir / "diff/%05d.png") + " --warn 1 --fail 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(dir / "r.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_EQ(j["frames"].size(), 3u);
  EXPECT_EQ(j["result"], "pass");
  EXPECT_NEAR(j["frames"][1]["max_abs"].get<double>(), 2.0 / 255.0, 1e-6);
  EXPECT_GT(j["frames"][1]["de2000_p99"].get<double>(), 0.1);
  EXPECT_LT(j["frames"][1]["de2000_p99"].get<double>(), 1.0);
  EXPECT_EQ(test::count_entries(dir.path() / "diff"), 3);
  const cv::Mat heat = cv::imread(dir / "diff/00000.png");
  EXPECT_EQ(heat.size(), cv::Size(64, 48));
}

// A chunk of a longer sequence (frames 120 to 122): the heat maps and the
// report's frames carry the input's numbers, so each sits beside its frame.
TEST(Compare, DiffMapsAreNamedByTheInputsFrameNumbers) {
  test::ScratchDir dir;
  const std::string a = write_sequence(dir, "a", 3, 0, cv::Size(64, 48), 120);
  const std::string b = write_sequence(dir, "b", 3, 1, cv::Size(64, 48), 120);
  const auto r = test::run_eyestream("compare " + a + " " + b + " --json " + (dir / "r.json") + " --diff-out " +
                                     (dir / "diff/%05d.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "diff/00120.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "diff/00122.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "diff/00000.png"));
  std::ifstream in(dir / "r.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["frames"][0]["frame"], 120);
  // Folders of numbered files keep the numbers, as their pattern would.
  const auto f = test::run_eyestream("compare " + (dir / "a") + " " + (dir / "b") + " --diff-out " +
                                     (dir / "folder/%05d.png"));
  ASSERT_EQ(f.exit_code, 0) << f.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "folder/00120.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "folder/00000.png"));
  // A numbered folder with a gap is refused as a pattern is, with a hint compare can follow.
  std::filesystem::remove(dir / "b/00121.png");
  const auto gap = test::run_eyestream("compare " + (dir / "a") + " " + (dir / "b"));
  EXPECT_EQ(gap.exit_code, 3) << gap.output;
  EXPECT_NE(gap.output.find("compare pairs every frame"), std::string::npos) << gap.output;
}

// Flat colours encoded as BT.709 limited-range 4:2:0 H.264 decode back to
// their code values: the reader honours the matrix and the range.
TEST(VideoReader, DecodesOwnH264BackToItsCodeValues) {
  test::ScratchDir dir;
  const cv::Vec3b colours[3] = {{128, 128, 128}, {200, 60, 30}, {20, 160, 220}};  // R, G, B
  {
    io::VideoOptions o;
    o.crf = 0;
    io::VideoWriter writer(dir / "flat.mp4", o);
    for (int i = 0; i < 3; ++i) {
      io::DisplayFrame f;
      f.code = cv::Mat(64, 64, CV_8UC3, cv::Scalar(colours[i][0], colours[i][1], colours[i][2]));
      f.index = i;
      f.time_s = i / 30.0;
      writer.write(f);
    }
    writer.finish();
  }
  io::VideoReader reader(dir / "flat.mp4");
  EXPECT_EQ(reader.width(), 64);
  EXPECT_EQ(reader.colour().matrix, "bt709");
  EXPECT_FALSE(reader.colour().full_range);
  for (int i = 0; i < 3; ++i) {
    const auto f = reader.next();
    ASSERT_TRUE(f) << i;
    EXPECT_NEAR(f->time_s, i / 30.0, 1e-3);
    const cv::Vec3f centre = f->rgb.at<cv::Vec3f>(32, 32);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c] * 255.0, colours[i][c], 1.5) << "frame " << i << " channel " << c;
  }
  EXPECT_FALSE(reader.next());
}

}  // namespace
}  // namespace eyestream
