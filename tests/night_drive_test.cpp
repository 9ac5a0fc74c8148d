#include <gtest/gtest.h>

#include <algorithm>

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

TEST(NightDrive, WritesHalfFloatFramesInCandelasWithGazeAndABlink) {
  test::ScratchDir dir;
  SceneOptions o;
  o.out_dir = dir.path().string();
  o.width = 320;
  o.height = 180;
  find_scene("night-drive").generate(o);

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
