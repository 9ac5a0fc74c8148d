// The library API (eyestream/eye.hpp): the command line's model path, bit
// for bit; settings by the command line's names, with its messages; the
// eye's state saved and restored; frames by pointer and stride.
#include <eyestream/eye.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <thread>

#include "io/exr_file.hpp"
#include "io/exr_sequence_source.hpp"
#include "io/gaze_import.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

struct Clip {
  std::vector<cv::Mat> frames;
  std::vector<std::vector<Gaze>> gaze;  // per frame, the samples in its interval
  double fps = 30.0;
};

Clip load_clip(const test::ScratchDir& dir) {
  Clip c;
  io::ExrSequenceSource source(dir / "h/frames", {});
  c.fps = source.info().frames_per_second;
  io::GazeImportOptions o;
  o.frame_width = source.info().width;
  o.frame_height = source.info().height;
  const std::vector<io::GazeSample> samples = io::read_gaze(dir / "h/gaze.csv", o);
  while (auto f = source.next()) {
    const double t0 = f->index / c.fps, t1 = (f->index + 1) / c.fps;
    std::vector<Gaze> in;
    for (const io::GazeSample& s : samples)
      if (s.t_s >= t0 && s.t_s < t1)
        in.push_back({s.t_s, s.x, s.y, s.state == io::EyeState::kClosed, s.state == io::EyeState::kLost});
    c.frames.push_back(f->rgb.clone());
    c.gaze.push_back(in);
  }
  return c;
}

// The headlights sample, 64x36 for `seconds`, rendered into dir/h and
// loaded (empty when `eyestream sample` fails).
Clip sample_clip(const test::ScratchDir& dir, double seconds) {
  if (test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 64 --height 36 --duration " +
                          std::to_string(seconds))
          .exit_code != 0)
    return {};
  return load_clip(dir);
}

// A gaze log moving every 10 ms, with a blink across the end of frame 2
// and lost samples across the end of frame 5 (30 frames/s).
void write_gaze_with_blink_and_loss(const std::string& path) {
  std::string csv = "t,x,y,event\n";
  for (int i = 0; i < 40; ++i) {
    const double t = 0.01 * i;
    char line[96];
    const char* event = (t >= 0.085 && t < 0.145) ? "blink" : (t >= 0.185 && t < 0.235) ? "lost" : "";
    if (*event)
      std::snprintf(line, sizeof line, "%.3f,,,%s\n", t, event);
    else
      std::snprintf(line, sizeof line, "%.3f,%.1f,%.1f,\n", t, 10.0 + 1.3 * i, 8.0 + 0.5 * i);
    csv += line;
  }
  std::ofstream(path) << csv;
}

TEST(LibraryApi, AnEyeComputesWhatTheCommandLineComputes) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 64 --height 36 --duration 0.4")
                .exit_code,
            0);
  write_gaze_with_blink_and_loss(dir / "h/gaze.csv");
  const auto r = test::run_eyestream("run -i " + (dir / "h/frames") + " -g " + (dir / "h/gaze.csv") + " -o " +
                                     (dir / "e/%05d.exr") + " --quality fast --viewer-age 70");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Clip clip = load_clip(dir);
  ASSERT_GE(clip.frames.size(), 10u);
  Eye eye(64, 36, clip.fps, {{"quality", "fast"}, {"viewer_age", "70"}});
  for (size_t i = 0; i < clip.frames.size(); ++i) {
    const Frame out = eye.process(clip.frames[i], clip.gaze[i]);
    char name[32];
    std::snprintf(name, sizeof name, "e/%05d.exr", int(i));
    const io::ExrImage cli = io::read_exr(dir / name, 1 << 20);
    ASSERT_EQ(cv::norm(out.linear, cli.rgb, cv::NORM_INF), 0.0) << "frame " << i;
    EXPECT_EQ(out.code.type(), CV_8UC3);
    EXPECT_GT(out.report.adaptation_cd_m2, 0.0);
    EXPECT_GT(out.report.pupil_mm, 1.0);
  }
}

// The whole recording handed over at once (set_gaze) is read as the
// command line reads its log: the first sample (at 50 ms, in frame 1) held
// back to frame 0, the recorded pupil bridged across the blink, and the
// target's luminances in the report; the frames are the command line's
// byte for byte.
TEST(LibraryApi, AWholeRecordingGivesTheCommandLinesFramesAndReport) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 64 --height 36 --duration 0.4")
                .exit_code,
            0);
  std::string csv = "t,x,y,event,pupil_mm\n";
  std::vector<Gaze> recording;
  for (int i = 5; i < 40; ++i) {
    const double t = 0.01 * i;
    const bool blink = t >= 0.145 && t < 0.205;
    char line[96];
    if (blink) std::snprintf(line, sizeof line, "%.3f,,,blink,\n", t);
    else std::snprintf(line, sizeof line, "%.3f,%.1f,%.1f,,%.2f\n", t, 50.0 - 1.1 * i, 20.0 - 0.3 * i, 3.0 + 0.05 * i);
    csv += line;
    recording.push_back({t, blink ? 0.0 : 50.0 - 1.1 * i, blink ? 0.0 : 20.0 - 0.3 * i, blink, false,
                         blink ? NAN : 3.0 + 0.05 * i});
  }
  std::ofstream(dir / "g.csv") << csv;
  const std::string options = " --quality fast --pupil-from-gaze --target 20,10,8,6";
  const auto r = test::run_eyestream("run -i " + (dir / "h/frames") + " -g " + (dir / "g.csv") + " -o " +
                                     (dir / "e/%05d.exr") + " --report " + (dir / "r.csv") + options);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows = test::csv_rows(dir / "r.csv");
  const Clip clip = load_clip(dir);
  ASSERT_EQ(rows.size(), clip.frames.size());
  const std::map<std::string, std::string> settings = {
      {"quality", "fast"}, {"pupil-from-gaze", "true"}, {"target", "20,10,8,6"}, {"report", "true"}};
  Eye eye(64, 36, clip.fps, settings), framewise(64, 36, clip.fps, settings);
  eye.set_gaze(recording);
  for (size_t i = 0; i < clip.frames.size(); ++i) {
    const Frame out = eye.process(clip.frames[i]);
    char name[32];
    std::snprintf(name, sizeof name, "e/%05d.exr", int(i));
    ASSERT_EQ(cv::norm(out.linear, io::read_exr(dir / name, 1 << 20).rgb, cv::NORM_INF), 0.0) << "frame " << i;
    const FrameReport& a = out.report;
    EXPECT_NEAR(a.pupil_mm, std::stod(rows[i].at("pupil_mm")), 1e-5 * a.pupil_mm) << "frame " << i;
    EXPECT_NEAR(a.target_cd_m2, std::stod(rows[i].at("target_cd_m2")), 1e-5 * a.target_cd_m2) << "frame " << i;
    EXPECT_NEAR(a.background_cd_m2, std::stod(rows[i].at("background_cd_m2")), 1e-5 * a.background_cd_m2);
    EXPECT_GT(a.target_cd_m2, 0.0);
    EXPECT_GT(a.glare_ms + a.adaptation_ms + a.retina_ms + a.mesopic_ms + a.afterimage_ms, 0.0);
    EXPECT_EQ(a.nonfinite_pixels, 0);
  }
  // Frame by frame, frame 0 has no sample yet and looks at the centre: the
  // whole recording is what makes the first frame the command line's.
  const Frame first = framewise.process(clip.frames[0]);
  EXPECT_EQ(first.report.gaze_x, 32.0);
  EXPECT_NE(std::stod(rows[0].at("gaze_x")), 32.0);
  EXPECT_THROW(eye.process(clip.frames[0], {{0.5, 1.0, 1.0}}), Error) << "samples beside a recording";
}

TEST(LibraryApi, TheFramesReportHasTheCommandLinesVeilAndTi) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 64 --height 36 --duration 0.3")
                .exit_code,
            0);
  const auto r = test::run_eyestream("run -i " + (dir / "h/frames") + " -g " + (dir / "h/gaze.csv") + " -o " +
                                     (dir / "e/%05d.png") + " --quality fast --report " + (dir / "r.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows = test::csv_rows(dir / "r.csv");
  const Clip clip = load_clip(dir);
  ASSERT_EQ(rows.size(), clip.frames.size());
  Eye with(64, 36, clip.fps, {{"quality", "fast"}, {"report", "true"}}), without(64, 36, clip.fps, {{"quality", "fast"}});
  for (size_t i = 0; i < clip.frames.size(); ++i) {
    const FrameReport a = with.process(clip.frames[i], clip.gaze[i]).report;
    const FrameReport b = without.process(clip.frames[i], clip.gaze[i]).report;
    // The CSV prints 6 significant digits.
    EXPECT_NEAR(a.veil_cd_m2, std::stod(rows[i].at("veil_cd_m2")), 1e-5 * a.veil_cd_m2) << "frame " << i;
    EXPECT_NEAR(a.ti_percent, std::stod(rows[i].at("ti_percent")), 1e-5 * a.ti_percent) << "frame " << i;
    EXPECT_NEAR(a.peak_cd_m2, std::stod(rows[i].at("peak_cd_m2")), 1e-5 * a.peak_cd_m2) << "frame " << i;
    EXPECT_GT(a.veil_cd_m2, 0.0);
    EXPECT_EQ(b.veil_cd_m2, -1.0) << "not asked for";
  }
  EXPECT_THROW(Eye(8, 8, 30.0, {{"report", "yes"}}), Error);
}

TEST(LibraryApi, SettingsByTheCommandLinesNamesAndItsMessages) {
  EXPECT_NO_THROW(Eye(32, 18, 30.0, {{"viewer-age", "70"}, {"quality", "reference"}}));
  try {
    Eye(32, 18, 30.0, {{"viewer-agee", "70"}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.exit_code(), 2);
    EXPECT_NE(std::string(e.what()).find("did you mean 'viewer-age'?"), std::string::npos) << e.what();
  }
  try {
    Eye(32, 18, 30.0, {{"viewer-age", "500"}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("viewer-age"), std::string::npos) << e.what();
  }
  Eye eye(32, 18, 30.0);
  EXPECT_THROW(eye.process(cv::Mat(17, 32, CV_32FC3, cv::Scalar::all(1.0))), Error);
}

TEST(LibraryApi, StateRestoresAndPointersWork) {
  test::ScratchDir dir;
  const Clip clip = sample_clip(dir, 0.3);
  ASSERT_FALSE(clip.frames.empty());
  // The state is a snapshot: taken after frame 3, restored after the
  // saving eye has gone on, it still continues from frame 4.
  Eye a(64, 36, clip.fps), b(64, 36, clip.fps);
  for (size_t i = 0; i < 4; ++i) a.process(clip.frames[i], clip.gaze[i]);
  const Eye::State saved = a.state();
  std::vector<Frame> later;
  for (size_t i = 4; i < clip.frames.size(); ++i) later.push_back(a.process(clip.frames[i], clip.gaze[i]));
  b.restore(saved);
  for (size_t i = 4; i < clip.frames.size(); ++i) {
    const cv::Mat& m = clip.frames[i];
    const Frame fb = b.process(m.ptr<float>(), m.step, clip.gaze[i]);
    ASSERT_EQ(cv::norm(later[i - 4].linear, fb.linear, cv::NORM_INF), 0.0) << "frame " << i;
    ASSERT_EQ(cv::norm(later[i - 4].code, fb.code, cv::NORM_INF), 0.0) << "frame " << i;
  }
  EXPECT_THROW(b.process(nullptr, 0), Error);
  Eye::State bad = saved;
  bad.numbers[0] = NAN;
  EXPECT_THROW(b.restore(bad), Error);
}

// Independent eyes on threads of their own at the same time give what each
// gives alone (the model's shared tables and FFT plans are made under locks).
TEST(LibraryApi, IndependentEyesOnTwoThreadsGiveWhatEachGivesAlone) {
  test::ScratchDir dir;
  const Clip clip = sample_clip(dir, 0.3);
  ASSERT_FALSE(clip.frames.empty());
  const std::vector<std::map<std::string, std::string>> settings = {{{"quality", "fast"}},
                                                                    {{"quality", "reference"}, {"viewer-age", "70"}}};
  std::vector<std::vector<cv::Mat>> alone(settings.size()), together(settings.size());
  for (size_t e = 0; e < settings.size(); ++e) {
    Eye eye(64, 36, clip.fps, settings[e]);
    for (size_t i = 0; i < clip.frames.size(); ++i) alone[e].push_back(eye.process(clip.frames[i], clip.gaze[i]).linear.clone());
  }
  std::vector<std::thread> threads;
  for (size_t e = 0; e < settings.size(); ++e)
    threads.emplace_back([&, e] {
      Eye eye(64, 36, clip.fps, settings[e]);
      for (size_t i = 0; i < clip.frames.size(); ++i)
        together[e].push_back(eye.process(clip.frames[i], clip.gaze[i]).linear.clone());
    });
  for (std::thread& t : threads) t.join();
  for (size_t e = 0; e < settings.size(); ++e)
    for (size_t i = 0; i < clip.frames.size(); ++i)
      ASSERT_EQ(cv::norm(alone[e][i], together[e][i], cv::NORM_INF), 0.0) << "eye " << e << ", frame " << i;
  EXPECT_GT(cv::norm(alone[0].back(), alone[1].back(), cv::NORM_INF), 0.0) << "two different eyes";
}

}  // namespace
}  // namespace eyestream
