// The viewer's own pupil (--pupil-from-gaze): the diameter the eye tracker
// recorded, read from native logs, Tobii Pro Lab exports, EyeLink ASC
// files, Pupil Core and Neon exports, bridged across a blink, drives the optics; the report shows it
// beside the model's. The expected diameters are computed here from the
// fixtures' own numbers.
#include <eyestream/eye.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "io/error.hpp"
#include "io/exr_file.hpp"
#include "io/gaze_import.hpp"
#include "pipeline/eye/gaze_timeline.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

// The recording: a sample every 10 ms from 5 ms (so none falls on a frame's
// edge at 30 or 60 frames/s) for 0.5 s at 120 x 60 px, the pupil 3 + 2 t
// mm (t seconds), the eye closed from 0.10 to 0.20 s (no pupil). The
// exports' clocks read 1000 ms at the first sample; --gaze-sync 0.995 puts
// it at 5 ms.
constexpr double kStep = 0.01, kFirst = 0.005, kEnd = 0.5;
bool closed_at(double t) { return t >= 0.0999 && t < 0.1999; }
double sample_time(int i) { return kFirst + i * kStep; }
double pupil_at(double t) { return 3.0 + 2.0 * t; }

// What the report should say for frame n at `fps`: the mean of the open
// samples' diameters inside [n / fps, (n + 1) / fps), or across the blink
// the line between the samples either side, at the interval's middle.
double expected_pupil(int n, double fps) {
  const double t0 = n / fps, t1 = (n + 1) / fps;
  double sum = 0.0, before_t = -1, after_t = -1;
  int count = 0;
  for (int i = 0; sample_time(i) < kEnd; ++i) {
    const double t = sample_time(i);
    if (closed_at(t)) continue;
    if (t >= t0 && t < t1) sum += pupil_at(t), ++count;
    if (t < t0) before_t = t;
    if (t >= t1 && after_t < 0) after_t = t;
  }
  if (count > 0) return sum / count;
  if (before_t < 0) return pupil_at(after_t);  // before the first sample: the first
  const double mid = 0.5 * (t0 + t1), w = (mid - before_t) / (after_t - before_t);
  return pupil_at(before_t) + w * (pupil_at(after_t) - pupil_at(before_t));
}

std::string native_log() {
  std::ostringstream o;
  o << "t,x,y,event,pupil_mm\n";
  for (int i = 0; sample_time(i) < kEnd; ++i) {
    const double t = sample_time(i);
    if (closed_at(t))
      o << t << ",,,blink,\n";
    else
      o << t << ",60,30,fixation," << pupil_at(t) << "\n";
  }
  return o.str();
}

// Tobii: both eyes, the left 0.1 mm larger (their mean is the recording),
// decimal commas, the left eye invalid in one sample (the right alone is
// the recording there), and no blink events: the closed eye's samples are
// invalid (lost), and bridged the same way.
std::string tobii_log() {
  std::ostringstream o;
  o << "Recording timestamp [ms]\tGaze point X\tGaze point Y\tValidity left\tValidity right\t"
       "Pupil diameter left [mm]\tPupil diameter right [mm]\n";
  auto comma = [](double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    std::string text = s.str();
    for (char& c : text)
      if (c == '.') c = ',';
    return text;
  };
  for (int i = 0; sample_time(i) < kEnd; ++i) {
    const double t = sample_time(i), clock = 1000 + 10 * i;
    if (closed_at(t)) {
      o << comma(clock) << "\t\t\tInvalid\tInvalid\t\t\n";
    } else if (i == 30) {
      o << comma(clock) << "\t60\t30\tInvalid\tValid\t9,9\t" << comma(pupil_at(t)) << "\n";
    } else {
      o << comma(clock) << "\t60\t30\tValid\tValid\t" << comma(pupil_at(t) + 0.05) << "\t"
        << comma(pupil_at(t) - 0.05) << "\n";
    }
  }
  return o.str();
}

// EyeLink: a calibration block, the pupil recorded as a diameter in the
// tracker's units (100 per mm here: --gaze-pupil-scale 0.01), blinks as
// SBLINK / EBLINK.
std::string eyelink_log() {
  std::ostringstream o;
  o << "** CONVERTED FROM rec.edf using edfapi\nMSG\t900 DISPLAY_COORDS 0 0 119 59\n"
       "MSG\t950 !CAL VALIDATION\n  0.5 0.3\nSTART\t1000 \tLEFT\tSAMPLES\tEVENTS\nPUPIL\tDIAMETER\n";
  bool in_blink = false;
  for (int i = 0; sample_time(i) < kEnd; ++i) {
    const double t = sample_time(i);
    const double ms = 1000 + 10 * i;
    if (closed_at(t) && !in_blink) o << "SBLINK L " << ms << "\n", in_blink = true;
    if (!closed_at(t) && in_blink) o << "EBLINK L " << ms - 100 << " " << ms << " 100\n", in_blink = false;
    if (closed_at(t))
      o << ms << "\t   .\t   .\t    0.0\t...\n";
    else
      o << ms << "\t  60.0\t  30.0\t " << 100 * pupil_at(t) << "\t...\n";
  }
  o << "END\t" << 1000 + 1000 * kEnd << " \tSAMPLES\tEVENTS\n";  // (after the last sample)
  return o.str();
}

// Pupil Core (a Pupil Player export's folder): gaze_positions.csv on the
// Pupil clock (s), the blink in blinks.csv, and pupil_positions.csv as
// Pupil Player writes it: each eye at its own times (eye0, the right eye,
// 2 ms before each gaze sample, eye1 2 ms after), a 2d-detector row
// (pixels, no diameter_3d) and a 3d-model row per sample, the left eye
// 0.1 mm larger, confidence 0 during the blink.
std::vector<std::pair<std::string, std::string>> pupil_core_export() {
  std::ostringstream gaze, pupils;
  gaze << "gaze_timestamp,world_index,confidence,norm_pos_x,norm_pos_y,base_data,gaze_point_3d_x\n";
  pupils << "pupil_timestamp,world_index,eye_id,confidence,norm_pos_x,norm_pos_y,diameter,method,ellipse_center_x,"
            "ellipse_center_y,ellipse_axis_a,ellipse_axis_b,ellipse_angle,diameter_3d,model_confidence,model_id\n";
  gaze.precision(10);
  pupils.precision(10);
  const int samples = int(std::lround((kEnd - kFirst) / kStep));
  for (int i = -1; i <= samples; ++i) {  // the eye cameras run a sample longer at each end
    const double t = sample_time(i), clock = 1.0 + kStep * i;
    if (i >= 0 && i < samples) gaze << clock << "," << i << "," << (closed_at(t) ? 0.1 : 0.95) << ",0.5,0.5,x,0\n";
    for (const int eye : {0, 1}) {
      const double te = t + (eye ? 0.002 : -0.002), confidence = closed_at(te) ? 0.0 : 0.97;
      const double mm = pupil_at(te) + (eye ? 0.05 : -0.05);
      pupils << clock + (te - t) << "," << i << "," << eye << "," << confidence << ",0.5,0.5,31.2,2d c++,96,96,30,32,"
             << "10,9.9,,\n";  // (a diameter_3d the 2d detector's rows must not give)
      pupils << clock + (te - t) << "," << i << "," << eye << "," << confidence << ",0.5,0.5,31.2,pye3d 0.3.0 "
             << "real-time,96,96,30,32,10," << (confidence > 0 ? mm : 0.0) << ",0.9,1\n";
    }
  }
  const std::string blinks = "id,start_timestamp,duration,end_timestamp,start_frame_index,index,end_frame_index,"
                             "confidence,filter_response,base_data\n1,1.1,0.09,1.19,10,15,19,0.8,0.5 0.6,x\n";
  return {{"gaze_positions.csv", gaze.str()}, {"blinks.csv", blinks}, {"pupil_positions.csv", pupils.str()}};
}

// Neon (a Pupil Cloud download's folder): gaze.csv with the blink's id, and
// 3d_eye_states.csv at the gaze's timestamps [ns] with both eyes'
// diameters (left 0.1 mm larger), still written during the blink.
std::vector<std::pair<std::string, std::string>> neon_export() {
  std::ostringstream gaze, eyes;
  gaze << "section id,recording id,timestamp [ns],gaze x [px],gaze y [px],worn,fixation id,blink id,"
          "azimuth [deg],elevation [deg]\n";
  eyes << "section id,recording id,timestamp [ns],pupil diameter left [mm],pupil diameter right [mm],"
          "eyeball center left x [mm],eyeball center left y [mm],eyeball center left z [mm],"
          "optical axis left x,optical axis left y,optical axis left z\n";
  eyes.precision(10);
  for (int i = 0; sample_time(i) < kEnd; ++i) {
    const double t = sample_time(i);
    const long long ns = 1000000000LL + 10000000LL * i;
    gaze << "s1,rec-a," << ns << ",800,600,1.0,," << (closed_at(t) ? "1" : "") << ",0,0\n";
    eyes << "s1,rec-a," << ns << "," << pupil_at(t) + 0.05 << "," << pupil_at(t) - 0.05 << ",30,10,-40,0,0,1\n";
  }
  return {{"gaze.csv", gaze.str()}, {"3d_eye_states.csv", eyes.str()}};
}

TEST(RecordedPupil, PupilLabsFilesAverageTheEyesAndSkipTheDetectorsRows) {
  io::GazeImportOptions o;
  o.frame_width = 120;
  o.frame_height = 60;
  o.sync_clock = 0.995;
  for (const auto& files : {pupil_core_export(), neon_export()}) {
    io::GazeImportOptions with = o;
    with.pupils_text = files.back().second;
    with.pupils_name = files.back().first;
    io::GazeRead read;
    const std::vector<io::GazeSample> s = io::parse_gaze(files.front().second, files.front().first, with, &read);
    ASSERT_EQ(s.size(), 50u);
    for (size_t i = 0; i < s.size(); ++i) {
      if (!closed_at(sample_time(int(i)))) {
        EXPECT_NEAR(s[i].pupil_mm, pupil_at(sample_time(int(i))), 1e-9) << files.back().first << " sample " << i;
      }
    }
    EXPECT_NE(read.notes.back().find("pupil diameters from " + files.back().first), std::string::npos);
    with.eye = "left";
    EXPECT_NEAR(io::parse_gaze(files.front().second, files.front().first, with).at(40).pupil_mm,
                pupil_at(sample_time(40)) + 0.05, 1e-9)
        << "--gaze-eye left";
  }
  // An older Neon export's single column; a Pupil Core file without diameter_3d names it.
  io::GazeImportOptions old = o;
  old.pupils_text = "section id,recording id,timestamp [ns],pupil diameter [mm]\ns1,rec-a,1000000000,4.25\n";
  old.pupils_name = "3d_eye_states.csv";
  EXPECT_NEAR(io::parse_gaze(neon_export().front().second, "gaze.csv", old).at(0).pupil_mm, 4.25, 1e-12);
  // A download's file holding two recordings: the gaze's own is read.
  old.pupils_text = "section id,recording id,timestamp [ns],pupil diameter [mm]\ns1,rec-b,1000000000,6.5\n"
                    "s1,rec-a,1000000000,4.25\n";
  EXPECT_NEAR(io::parse_gaze(neon_export().front().second, "gaze.csv", old).at(0).pupil_mm, 4.25, 1e-12);
  // Diameters outside 1-10 mm (the 3d model's outliers) are none, and noted.
  old.pupils_text = "section id,recording id,timestamp [ns],pupil diameter [mm]\ns1,rec-a,1000000000,1e6\n";
  io::GazeRead read;
  EXPECT_TRUE(std::isnan(io::parse_gaze(neon_export().front().second, "gaze.csv", old, &read).at(0).pupil_mm));
  EXPECT_NE(read.notes.front().find("1 pupil diameters outside 1-10 mm"), std::string::npos) << read.notes.front();
  old.pupils_text = "section id,recording id,timestamp [ns],pupil diameter [mm]\n";
  EXPECT_THROW(io::parse_gaze(neon_export().front().second, "gaze.csv", old), InputError) << "no rows";
  old.pupils_text = "pupil_timestamp,eye_id,confidence,diameter\n1.0,0,1,30\n";
  old.pupils_name = "pupil_positions.csv";
  try {
    io::parse_gaze(pupil_core_export().front().second, "gaze_positions.csv", old);
    ADD_FAILURE() << "no diameter_3d";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pupil_positions.csv:1: no column 'diameter_3d'"), std::string::npos)
        << e.what();
  }
}

TEST(RecordedPupil, TheTimelineAveragesInsideAFrameAndBridgesABlink) {
  std::vector<io::GazeSample> samples;
  for (int i = 0; sample_time(i) < kEnd; ++i) {
    const double t = sample_time(i);
    io::GazeSample s{t, 60, 30, closed_at(t) ? io::EyeState::kClosed : io::EyeState::kOpen};
    if (!closed_at(t)) s.pupil_mm = pupil_at(t);
    samples.push_back(s);
  }
  const pipeline::GazeTimeline timeline(samples, 60, 30);
  for (int n = 0; n < 15; ++n)
    EXPECT_NEAR(*timeline.recorded_pupil_mm(n / 30.0, (n + 1) / 30.0), expected_pupil(n, 30.0), 1e-9) << n;
  EXPECT_NEAR(timeline.segments(0.13, 0.16).front().recorded_pupil_mm, pupil_at(0.145), 1e-9)
      << "inside the blink: on the line from 0.095 s to 0.205 s";
  EXPECT_FALSE(pipeline::GazeTimeline({{0.0, 1, 1}}, 0, 0).recorded_pupil_mm(0, 1)) << "no diameter recorded";
}

// Each format through the command line, at two frame rates: the report's
// pupil_mm is the recording's, pupil_model_mm the model's, and the veil
// follows the recorded pupil.
TEST(RecordedPupil, EachFormatsRecordingDrivesTheOpticsThroughTheCommandLine) {
  test::ScratchDir dir;
  // Each format's files (the log first, then what lies beside it).
  const struct {
    const char* name;
    std::vector<std::pair<std::string, std::string>> files;
    std::string options;
  } formats[] = {{"native", {{"log.csv", native_log()}}, ""},  // (Tobii exports carry no blinks)
                 {"tobii", {{"export.tsv", tobii_log()}}, " --gaze-format tobii --gaze-sync 0.995"},
                 {"eyelink", {{"rec.asc", eyelink_log()}},
                  " --gaze-format eyelink --gaze-sync 0.995 --gaze-pupil-scale 0.01"},
                 {"core", pupil_core_export(), " --gaze-sync 0.995"},
                 {"neon", neon_export(), " --gaze-sync 0.995"}};
  for (const char* fps : {"30", "60"}) {
    const std::string scene = dir / (std::string("h") + fps);
    ASSERT_EQ(test::run_eyestream("sample headlights -o " + scene + " --width 120 --height 60 --fps " + fps +
                                  " --duration 0.4")
                  .exit_code,
              0);
    for (const auto& f : formats) {
      std::filesystem::create_directories(dir / f.name);
      for (const auto& [file, text] : f.files) std::ofstream(dir / f.name + "/" + file, std::ios::binary) << text;
      const std::string log = dir / f.name + "/" + f.files.front().first;
      const std::string report = dir / (std::string(fps) + f.name + ".csv");
      const auto r = test::run_eyestream("run -i " + scene + "/frames -g " + log + f.options + " --pupil-from-gaze -o " +
                                         dir / (std::string(fps) + f.name + ".mp4") + " --report " + report);
      ASSERT_EQ(r.exit_code, 0) << f.name << ": " << r.output;
      const auto rows = test::csv_rows(report);
      ASSERT_GE(rows.size(), 10u);
      bool blink_bridged = false;
      for (size_t n = 0; n < rows.size(); ++n) {
        const double expected = expected_pupil(int(n), std::stod(fps));
        EXPECT_NEAR(std::stod(rows[n].at("pupil_mm")), expected, 2e-5 * expected) << f.name << " frame " << n;
        EXPECT_NEAR(std::stod(rows[n].at("pupil_recorded_mm")), expected, 2e-5 * expected) << f.name;
        EXPECT_GT(std::abs(std::stod(rows[n].at("pupil_model_mm")) - expected), 0.05) << "the model differs";
        blink_bridged |= rows[n].at("eye") == "closed";
      }
      if (std::string(f.name) != "tobii") {
        EXPECT_TRUE(blink_bridged) << f.name << ": a frame inside the blink";
      }
    }
  }
  // The optics follow the recording: in scotopic light (the dusk scene at
  // 0.01 cd/m^2) the lenticular halo needs a pupil over 2.5 mm and is
  // whole from 3.5 mm (psf_weights.hpp), so the recorded 3.0-3.9 mm and the
  // model's wide pupil give different retinal images.
  ASSERT_EQ(test::run_eyestream("sample dusk -o " + dir / "d" + " --width 120 --height 60 --duration 0.2 --luminance 0.01")
                .exit_code,
            0);
  for (const bool recorded : {true, false}) {
    const auto r = test::run_eyestream("run -i " + dir / "d/frames" + " -g " + dir / "native/log.csv" + " -o " +
                                       dir / (recorded ? "r/%05d.exr" : "m/%05d.exr") + " --report " +
                                       dir / (recorded ? "r.csv" : "m.csv") + (recorded ? " --pupil-from-gaze" : ""));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const cv::Mat with = io::read_exr(dir / "r/00000.exr", 1 << 20).rgb, without = io::read_exr(dir / "m/00000.exr", 1 << 20).rgb;
  EXPECT_GT(cv::norm(with, without, cv::NORM_INF), 0.0);
  EXPECT_EQ(test::csv_rows(dir / "m.csv")[0].at("pupil_recorded_mm"), "") << "not asked for";
}

// EyeLink records pupil area by default: the diameter is the scale times
// its square root; binocular files average the two eyes' diameters.
TEST(RecordedPupil, EyeLinkAreasAndBinocularPupils) {
  io::GazeImportOptions o;
  o.frame_width = 1000;
  o.frame_height = 500;
  o.pupil_scale_mm = 0.1;
  const std::string area = "MSG\t1000 DISPLAY_COORDS 0 0 999 499\nSTART\t2000 \tLEFT\tSAMPLES\n"
                           "PUPIL\tAREA\n2000\t100.0\t200.0\t 900.0\t...\nEND\t2001\n";
  EXPECT_NEAR(io::parse_gaze(area, "a.asc", o).at(0).pupil_mm, 0.1 * 30.0, 1e-12);
  const std::string both = "MSG\t1000 DISPLAY_COORDS 0 0 999 499\nSTART\t2000 \tLEFT\tRIGHT\tSAMPLES\n"
                           "PUPIL\tDIAMETER\n2000\t100.0\t200.0\t 40.0\t110.0\t220.0\t 44.0\t.....\nEND\t2001\n";
  EXPECT_NEAR(io::parse_gaze(both, "b.asc", o).at(0).pupil_mm, 4.2, 1e-12);
  o.eye = "right";
  EXPECT_NEAR(io::parse_gaze(both, "b.asc", o).at(0).pupil_mm, 4.4, 1e-12);
  o.pupil_scale_mm = 0.0;
  EXPECT_TRUE(std::isnan(io::parse_gaze(both, "b.asc", o).at(0).pupil_mm)) << "no scale: not read";
}

TEST(RecordedPupil, ALogWithoutDiametersIsRefusedNamingTheOption) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample headlights -o " + dir / "h" + " --width 64 --height 36 --duration 0.1").exit_code,
            0);
  auto r = test::run_eyestream("run -i " + dir / "h/frames" + " -g " + dir / "h/gaze.csv" +
                               " --pupil-from-gaze -o " + dir / "x.mp4");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("eyestream: error: " + dir / "h/gaze.csv" + ": --pupil-from-gaze"), std::string::npos)
      << r.output;
  std::ofstream(dir / "rec.asc") << eyelink_log();
  r = test::run_eyestream("run -i " + dir / "h/frames" + " -g " + dir / "rec.asc" +
                          " --gaze-format eyelink --pupil-from-gaze -o " + dir / "y.mp4");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("--gaze-pupil-scale"), std::string::npos) << r.output;
  r = test::run_eyestream("run -i " + dir / "h/frames" + " --pupil-from-gaze -o " + dir / "z.mp4");
  EXPECT_EQ(r.exit_code, 2) << "no gaze log: " << r.output;
}

// The library: a pupil of 0 (how trackers mark a missing one, e.g. on a
// blink's samples) is no diameter, the last real one is carried, and the
// eye's state restores.
TEST(RecordedPupil, TheLibraryTakesZeroAsNoneAndKeepsTheLastDiameter) {
  const cv::Mat dark(36, 64, CV_32FC3, cv::Scalar::all(0.01));
  Eye a(64, 36, 30.0, {{"pupil-from-gaze", "true"}});
  EXPECT_NEAR(a.process(dark, {{0.0, 32, 18, false, false, 3.2}}).report.pupil_mm, 3.2, 1e-12);
  EXPECT_NEAR(a.process(dark, {{1 / 30.0, 32, 18, true, false, 0.0}}).report.pupil_mm, 3.2, 1e-12);
  const Eye::State saved = a.state();
  Eye b(64, 36, 30.0, {{"pupil-from-gaze", "true"}});
  ASSERT_NO_THROW(b.restore(saved));
  EXPECT_NEAR(b.process(dark, {{2 / 30.0, 32, 18, false, false, 0.0}}).report.pupil_mm, 3.2, 1e-12);
  EXPECT_NEAR(a.process(dark, {{2 / 30.0, 32, 18, false, false, 0.0}}).report.pupil_mm, 3.2, 1e-12);
}

}  // namespace
}  // namespace eyestream
