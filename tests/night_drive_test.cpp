#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "io/exr_file.hpp"
#include "io/exr_sequence_source.hpp"
#include "io/gaze_import.hpp"
#include "samples/scene.hpp"
#include "tests/test_support.hpp"

namespace eyestream::samples {
namespace {

double peak_luminance(const cv::Mat& rgb) {
  double peak = 0;
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x) {
      const cv::Vec3f p = rgb.at<cv::Vec3f>(y, x);
      peak = std::max(peak, 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]);
    }
  return peak;
}

// Generates `scene` at 320x180 into `dir`.
void generate(const std::string& scene, const test::ScratchDir& dir, double fps = 30.0) {
  SceneOptions o;
  o.out_dir = dir.path().string();
  o.width = 320;
  o.height = 180;
  o.fps = fps;
  find_scene(scene).generate(o);
}

TEST(NightDrive, WritesHalfFloatFramesInCandelasWithGazeAndABlink) {
  test::ScratchDir dir;
  generate("night-drive", dir);

  const io::ExrImage first = io::read_exr(dir / "frames/00000.exr", 1 << 24);
  ASSERT_TRUE(first.white_luminance);
  ASSERT_TRUE(first.frames_per_second);
  EXPECT_DOUBLE_EQ(*first.frames_per_second, 30.0);

  io::ExrSequenceSource source(dir / "frames/%05d.exr", {});
  EXPECT_EQ(source.info().frame_count, 180);
  std::vector<double> peaks, darkest;
  while (auto f = source.next()) {
    peaks.push_back(peak_luminance(f->rgb));
    double lo;
    cv::minMaxLoc(f->rgb.reshape(1), &lo);
    darkest.push_back(lo);
  }
  // Street lamps ~1e3-1e4 cd/m^2 at the start; the headlights, drawn by
  // energy, reach ~1e5 cd/m^2 at the end; the sky stays near 0.003-0.02.
  EXPECT_GT(peaks.front(), 1e3);
  EXPECT_LT(peaks.front(), 2e4);
  EXPECT_GT(peaks.back(), 5e4);
  EXPECT_LT(peaks.back(), 2e5);
  EXPECT_GT(*std::min_element(darkest.begin(), darkest.end()), 1e-3);
  EXPECT_LT(*std::max_element(darkest.begin(), darkest.end()), 0.05);

  io::GazeImportOptions frame;
  frame.frame_width = 320;
  frame.frame_height = 180;
  const auto gaze = io::read_gaze(dir / "gaze.csv", frame);
  EXPECT_GT(gaze.size(), 600u);
  EXPECT_TRUE(
      std::any_of(gaze.begin(), gaze.end(), [](const io::GazeSample& s) { return s.state == io::EyeState::kClosed; }));
  EXPECT_TRUE(std::all_of(gaze.begin(), gaze.end(),
                          [](const io::GazeSample& s) { return s.x >= 0 && s.x < 320 && s.y >= 0 && s.y < 180; }));
}

// The long drive: a target mask per frame, on the pedestrian while it is
// ahead and empty once passed; the pedestrian is dim (0.05-5 cd/m^2);
// the gaze rests on it during its fixations and the eyes close five times.
TEST(NightDrive, LongDriveHasAPedestrianTargetTheGazeVisitsAndBlinks) {
  test::ScratchDir dir;
  generate("night-drive-long", dir, 10.0);
  EXPECT_EQ(test::count_entries(dir.path() / "frames"), 200);
  ASSERT_EQ(test::count_entries(dir.path() / "target"), 200);
  const cv::Mat mask_at_1s = cv::imread(dir / "target/00010.png", cv::IMREAD_GRAYSCALE);
  ASSERT_GT(cv::countNonZero(mask_at_1s), 4);
  EXPECT_EQ(cv::countNonZero(cv::imread(dir / "target/00199.png", cv::IMREAD_GRAYSCALE)), 0) << "passed by 19.9 s";
  const cv::Mat frame = io::read_exr(dir / "frames/00010.exr", 1 << 24).rgb * 10.0;  // whiteLuminance 10
  cv::Mat luminance;
  cv::transform(frame, luminance, cv::Matx13f(0.2126f, 0.7152f, 0.0722f));
  const double pedestrian = cv::mean(luminance, mask_at_1s)[0];
  EXPECT_GT(pedestrian, 0.05);
  EXPECT_LT(pedestrian, 5.0);

  io::GazeImportOptions frame_size;
  frame_size.frame_width = 320;
  frame_size.frame_height = 180;
  const auto gaze = io::read_gaze(dir / "gaze.csv", frame_size);
  int closed = 0;
  for (size_t i = 0; i < gaze.size(); ++i)
    closed += gaze[i].state == io::EyeState::kClosed && (i == 0 || gaze[i - 1].state != io::EyeState::kClosed);
  EXPECT_EQ(closed, 5) << "five blinks";
  // At 2.5 s (a target fixation) the gaze is within 3 px of the mask's box.
  const auto at = std::find_if(gaze.begin(), gaze.end(), [](const io::GazeSample& s) { return s.t_s >= 2.5; });
  ASSERT_NE(at, gaze.end());
  const cv::Rect box = cv::boundingRect(cv::imread(dir / "target/00025.png", cv::IMREAD_GRAYSCALE));
  EXPECT_NEAR(at->x, box.x + box.width / 2.0, 3.0 + box.width / 2.0);
  EXPECT_NEAR(at->y, box.y + box.height / 2.0, 3.0 + box.height / 2.0);
}

TEST(NightDrive, UnknownSceneNamesTheScenes) {
  try {
    find_scene("day-drive");
    FAIL();
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("night-drive"), std::string::npos);
  }
}

}  // namespace
}  // namespace eyestream::samples
