// Scene-adaptive activation (stage_activity.hpp): stages skip what a frame
// does not need, and skipping changes the output by less than its stated
// tolerance (retina_stage.hpp: kRestTolerance).
#include <gtest/gtest.h>

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "pipeline/eye/eye_simulator.hpp"
#include "retina/display_encoding.hpp"
#include "tests/test_support.hpp"

namespace eyestream::pipeline {
namespace {

constexpr int kW = 96, kH = 54;
constexpr double kFps = 30.0;

// A still, patterned scene (grey, a white patch, a blue patch), scaled.
cv::Mat still_scene(float scale) {
  cv::Mat f = test::constant_frame(kW, kH, {0.2f * scale, 0.2f * scale, 0.2f * scale});
  cv::rectangle(f, cv::Rect(10, 10, 20, 20), cv::Scalar::all(scale), cv::FILLED);
  cv::rectangle(f, cv::Rect(60, 20, 20, 20), cv::Scalar(0.05 * scale, 0.05 * scale, 0.6 * scale), cv::FILLED);
  return f;
}

// One viewer watching `frames` (with a gaze per frame), with skipping on or
// off; keeps every output and report.
struct Watch {
  std::vector<cv::Mat> shown;
  std::vector<FrameReport> reports;
};

using Gaze = cv::Point2d;

Watch watch(const std::vector<cv::Mat>& frames, const std::vector<Gaze>& gaze, bool skip, Settings s = {}) {
  s.skip = skip;
  EyeSimulator eye(test::plan_for(s, kW, kH, kFps));
  Watch w;
  for (size_t i = 0; i < frames.size(); ++i) {
    const double t0 = double(i) / kFps, t1 = double(i + 1) / kFps;
    FrameReport r;
    w.shown.push_back(eye.process({frames[i], t0, std::int64_t(i), "test"}, {{t0, t1, gaze[i].x, gaze[i].y, false}}, &r)
                          .linear.clone());
    w.reports.push_back(r);
  }
  return w;
}

// Largest difference of the 8-bit display codes (no dither) of two runs.
double max_code_difference(const Watch& a, const Watch& b) {
  retina::EncodingParams e;
  e.dither = false;
  double worst = 0;
  for (size_t i = 0; i < a.shown.size(); ++i) {
    cv::Mat ca, cb;
    retina::encode_display(a.shown[i], 8, std::int64_t(i), e, ca);
    retina::encode_display(b.shown[i], 8, std::int64_t(i), e, cb);
    worst = std::max(worst, cv::norm(ca, cb, cv::NORM_INF));
  }
  return worst;
}

double max_linear_difference(const Watch& a, const Watch& b) {
  double worst = 0;
  for (size_t i = 0; i < a.shown.size(); ++i) worst = std::max(worst, cv::norm(a.shown[i], b.shown[i], cv::NORM_INF));
  return worst;
}

TEST(StageSkipping, DimStillFrameSkipsGlareRetinaAndAfterimagesWithinTolerance) {
  const std::vector<cv::Mat> frames(60, still_scene(30.0f));
  const std::vector<Gaze> gaze(60, Gaze(40, 27));
  const Watch on = watch(frames, gaze, true), off = watch(frames, gaze, false);
  // Full-image glare runs on the first two frames (the second keeps it:
  // glare_stage.hpp); the still frame then reuses it.
  EXPECT_TRUE(on.reports[1].active.glare);
  for (size_t i = 2; i < on.reports.size(); ++i) EXPECT_FALSE(on.reports[i].active.glare) << "frame " << i;
  for (const FrameReport& r : off.reports) {
    EXPECT_TRUE(r.active.glare);
    EXPECT_TRUE(r.active.retina);
    EXPECT_TRUE(r.active.afterimages);
  }
  // The viewer starts at rest on the first frame; after it nothing changes.
  int idle = 0;
  for (size_t i = 1; i < on.reports.size(); ++i)
    idle += !on.reports[i].active.retina && !on.reports[i].active.afterimages && !on.reports[i].active.glare;
  EXPECT_GE(idle, 55) << "frames skipped at rest";
  EXPECT_LE(max_linear_difference(on, off), 1e-4);
  EXPECT_LE(max_code_difference(on, off), 1.0);
}

TEST(StageSkipping, OnePixelChangedInAStillSceneRunsTheGlareAgain) {
  // The still-scene cache knows the last frame by its digest
  // (frame_digest.hpp): the smallest change of one pixel of one frame,
  // one float step, is a new frame, and so is the return to the old one.
  // A frame's glare is kept when it comes a second time (frames 1 and 7).
  std::vector<cv::Mat> frames(8, still_scene(30.0f));
  frames[5] = frames[5].clone();
  cv::Vec3f& p = frames[5].at<cv::Vec3f>(40, 70);
  p[1] = std::nextafter(p[1], 1e9f);
  const Watch on = watch(frames, std::vector<Gaze>(8, Gaze(40, 27)), true);
  for (size_t i = 1; i < 8; ++i) EXPECT_EQ(on.reports[i].active.glare, i == 1 || i == 5 || i == 6 || i == 7) << "frame " << i;
}

TEST(StageSkipping, FadingAfterimageKeepsTheRetinaAwakeUntilItIsGone) {
  // 2 s on the patches (gaze still), then 8 s of uniform grey: the local-
  // adaptation afterimage fades; the retina runs while it shows.
  std::vector<cv::Mat> frames(60, still_scene(1000.0f));
  frames.resize(300, test::constant_frame(kW, kH, {100, 100, 100}));
  const std::vector<Gaze> gaze(frames.size(), Gaze(48, 27));
  Settings s;
  s.glare = false;
  const Watch on = watch(frames, gaze, true, s), off = watch(frames, gaze, false, s);
  // While the afterimage shows it is drawn on every frame.
  size_t last_drawn = 0;
  for (size_t i = 60; i < frames.size(); ++i)
    if (on.reports[i].active.afterimages) last_drawn = i;
  for (size_t i = 60; i <= last_drawn; ++i) EXPECT_TRUE(on.reports[i].active.afterimages) << "frame " << i;
  EXPECT_GT(last_drawn, 90u) << "the afterimage lasts beyond 1 s";
  EXPECT_LT(last_drawn, frames.size() - 10) << "and the retina comes to rest before the end";
  EXPECT_FALSE(on.reports.back().active.retina);
  EXPECT_LE(max_linear_difference(on, off), 1e-4);
  EXPECT_LE(max_code_difference(on, off), 1.0);
}

TEST(StageSkipping, SkippedTimeIsCaughtUpExactlyWhenTheStimulusChanges) {
  // At rest on one scene for 3 s, then a jump of the gaze: the state after
  // the catch-up equals the state stepped frame by frame.
  std::vector<cv::Mat> frames(120, still_scene(50.0f));
  std::vector<Gaze> gaze(90, Gaze(20, 20));
  gaze.resize(120, Gaze(70, 30));
  Settings s;
  s.state_sites_per_pixel = 1.0;
  s.precision = "double";
  s.skip = true;
  EyeSimulator on(test::plan_for(s, kW, kH, kFps));
  s.skip = false;
  EyeSimulator off(test::plan_for(s, kW, kH, kFps));
  int skipped = 0;
  for (size_t i = 0; i < frames.size(); ++i) {
    const double t0 = double(i) / kFps, t1 = double(i + 1) / kFps;
    const io::SceneFrame f{frames[i], t0, std::int64_t(i), "test"};
    FrameReport r;
    on.process(f, {{t0, t1, gaze[i].x, gaze[i].y, false}}, &r);
    off.process(f, {{t0, t1, gaze[i].x, gaze[i].y, false}});
    skipped += !r.active.retina;
  }
  EXPECT_GE(skipped, 80);
  const double scale = on.retina().state().calcium_max();
  EXPECT_LE(cv::norm(on.retina().state().bleached(), off.retina().state().bleached(), cv::NORM_INF), 1e-9);
  EXPECT_LE(cv::norm(on.retina().state().deficit(), off.retina().state().deficit(), cv::NORM_INF), 1e-9 * scale);
}

TEST(StageSkipping, MovingGazeOverAStillSceneKeepsTheRetinaRunning) {
  const std::vector<cv::Mat> frames(40, still_scene(50.0f));
  std::vector<Gaze> gaze;
  for (int i = 0; i < 40; ++i) gaze.push_back(Gaze(20 + i, 27));
  const Watch on = watch(frames, gaze, true);
  for (size_t i = 1; i < on.reports.size(); ++i) EXPECT_TRUE(on.reports[i].active.retina) << "frame " << i;
}

TEST(StageSkipping, AFrameKnownUnchangedAtRestIsComparedAgainAfterTheStimulusMoved) {
  // At rest the retina knows a frame it found unchanged by the frame's
  // digest and the gaze (retina_stage.hpp), without carrying it to the
  // grid again. Scene A at rest, then B (3e-4 brighter: beyond the
  // stimulus tolerance), then A again: both step, A's frames rest again,
  // and a gaze moved by a pixel over the same frame steps.
  const cv::Mat a = still_scene(30.0f), b = a * (1.0 + 3e-4);
  std::vector<cv::Mat> frames(20, a);
  frames.push_back(b);
  frames.resize(40, a);
  std::vector<Gaze> gaze(35, Gaze(40, 27));
  gaze.resize(40, Gaze(41, 27));
  Settings s;
  s.glare = false;  // the retina sees the frame itself
  const Watch on = watch(frames, gaze, true, s), off = watch(frames, gaze, false, s);
  for (size_t i = 5; i < 20; ++i) EXPECT_FALSE(on.reports[i].active.retina) << "frame " << i;
  EXPECT_TRUE(on.reports[20].active.retina) << "B";
  EXPECT_TRUE(on.reports[21].active.retina) << "A again";
  for (size_t i = 23; i < 35; ++i) EXPECT_FALSE(on.reports[i].active.retina) << "frame " << i;
  EXPECT_TRUE(on.reports[35].active.retina) << "the gaze moved";
  EXPECT_LE(max_linear_difference(on, off), 1e-4);
}

TEST(StageSkipping, PhotopicFramesSkipMesopicWorkAndDarkOnesDoNot) {
  const std::vector<Gaze> gaze(10, Gaze(48, 27));
  const Watch bright = watch(std::vector<cv::Mat>(10, still_scene(50.0f)), gaze, true);
  const Watch dark = watch(std::vector<cv::Mat>(10, still_scene(0.05f)), gaze, true);
  EXPECT_FALSE(bright.reports.back().active.mesopic);
  EXPECT_FALSE(bright.reports.back().active.acuity);
  EXPECT_TRUE(dark.reports.back().active.mesopic);
  EXPECT_TRUE(dark.reports.back().active.acuity);
  const Watch forced = watch(std::vector<cv::Mat>(10, still_scene(50.0f)), gaze, false);
  EXPECT_TRUE(forced.reports.back().active.acuity) << "--no-skip runs the acuity stage";
}

}  // namespace
}  // namespace eyestream::pipeline
