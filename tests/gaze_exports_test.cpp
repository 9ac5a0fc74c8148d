// Eye-tracker exports as they really come: fixtures reproducing the
// structure of real files (older Pupil Player headers, Neon's worn as
// 1.0/0.0, blinks.csv beside the export, Neon Marker Mapper surfaces,
// exports holding several recordings, Tobii timestamps without a unit,
// binocular EyeLink files), and a byte-order mark with CRLF line ends in
// every format.
#include <gtest/gtest.h>

#include "tests/gaze_options.hpp"

#include <fstream>

#include "io/error.hpp"
#include "io/gaze_import.hpp"
#include "tests/test_support.hpp"

namespace eyestream::io {
namespace {

using test::frame_1000x500;

bool mentions(const GazeRead& r, const std::string& text) {
  for (const std::string& n : r.notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// Pupil Player before gaze_timestamp: "timestamp,index,confidence,...".
const std::string kOldPupilPlayer =
    "timestamp,index,confidence,norm_pos_x,norm_pos_y,base_data,gaze_point_3d_x,gaze_point_3d_y,gaze_point_3d_z\n"
    "5123.500,0,0.97,0.25,0.75,0-5123.498,1.0,2.0,300.0\n"
    "5123.508,0,0.20,0.5,0.5,0-5123.506,1.0,2.0,300.0\n"
    "5123.516,1,0.95,0.75,0.25,0-5123.514,1.0,2.0,300.0\n";

TEST(GazeExports, TheOlderPupilPlayerHeaderIsReadLikeTheCurrentOne) {
  ASSERT_EQ(detect_gaze_format(kOldPupilPlayer), GazeFormat::kPupilCore);
  GazeRead read;
  const auto s = parse_gaze(kOldPupilPlayer, "gaze_positions.csv", frame_1000x500(), &read);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_NEAR(s[2].t_s, 0.016, 1e-9);
  EXPECT_DOUBLE_EQ(s[0].x, 250.0);
  EXPECT_DOUBLE_EQ(s[0].y, 125.0) << "norm_pos_y 0.75 from the bottom";
  EXPECT_EQ(s[1].state, EyeState::kLost) << "confidence 0.2";
  EXPECT_TRUE(mentions(read, "older Pupil Player"));
}

const std::string kNeonHeader =
    "section id,recording id,timestamp [ns],gaze x [px],gaze y [px],worn,fixation id,blink id,azimuth [deg],"
    "elevation [deg]\n";

TEST(GazeExports, NeonWornAsOneOrZeroPointZero) {
  const std::string text = kNeonHeader +
                           "s1,r1,1700000000000000000,800,600,1.0,1,,0,0\n"
                           "s1,r1,1700000000005000000,800,600,0.0,,,0,0\n"  // not worn
                           "s1,r1,1700000000010000000,400,300,1.0,,,0,0\n";
  const auto s = parse_gaze(text, "gaze.csv", frame_1000x500());
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].state, EyeState::kOpen);
  EXPECT_EQ(s[1].state, EyeState::kLost) << "worn 0.0 is not worn";
  EXPECT_DOUBLE_EQ(s[2].x, 250.0);
}

// Pupil Player's blink detector and Neon both write blinks.csv beside the
// gaze; its blinks close the eye (the export's own clock).
TEST(GazeExports, BlinksBesideTheExportCloseTheEye) {
  test::ScratchDir dir;
  write(dir / "gaze_positions.csv", "gaze_timestamp,world_index,confidence,norm_pos_x,norm_pos_y,base_data\n"
                                    "100.00,0,0.9,0.5,0.5,x\n100.10,1,0.9,0.5,0.5,x\n100.20,2,0.9,0.5,0.5,x\n"
                                    "100.30,3,0.9,0.5,0.5,x\n");
  write(dir / "blinks.csv", "id,start_timestamp,duration,end_timestamp,start_frame_index,index,end_frame_index,"
                            "confidence,filter_response,base_data\n"
                            "1,100.05,0.2,100.25,1,1,2,0.8,0.5 0.6,x\n");
  GazeRead read;
  const auto core = read_gaze(dir / "gaze_positions.csv", frame_1000x500(), &read);
  ASSERT_EQ(core.size(), 4u);
  EXPECT_EQ(core[0].state, EyeState::kOpen);
  EXPECT_EQ(core[1].state, EyeState::kClosed);
  EXPECT_EQ(core[2].state, EyeState::kClosed);
  EXPECT_EQ(core[3].state, EyeState::kOpen);
  EXPECT_TRUE(mentions(read, "1 blinks from")) << (read.notes.empty() ? "" : read.notes[0]);

  test::ScratchDir neon;
  write(neon / "gaze.csv", kNeonHeader + "s,r,1000000000,800,600,1,,,0,0\ns,r,1100000000,800,600,1,,,0,0\n"
                                         "s,r,1200000000,800,600,1,,,0,0\n");
  write(neon / "blinks.csv", "section id,recording id,blink id,start timestamp [ns],end timestamp [ns],"
                             "duration [ms]\ns,r,1,1050000000,1150000000,100\n");
  const auto n = read_gaze(neon / "gaze.csv", frame_1000x500());
  ASSERT_EQ(n.size(), 3u);
  EXPECT_EQ(n[1].state, EyeState::kClosed);
  EXPECT_EQ(n[2].state, EyeState::kOpen);
}

// A blinks.csv that does not belong to the export is left out with
// --gaze-blinks none; one kept elsewhere is named by its path.
TEST(GazeExports, BlinksCanBeLeftOutOrNamed) {
  test::ScratchDir dir;
  write(dir / "gaze_positions.csv", "gaze_timestamp,world_index,confidence,norm_pos_x,norm_pos_y,base_data\n"
                                    "100.00,0,0.9,0.5,0.5,x\n100.10,1,0.9,0.5,0.5,x\n100.20,2,0.9,0.5,0.5,x\n");
  const std::string blinks = "id,start_timestamp,duration,end_timestamp,start_frame_index,index,end_frame_index,"
                             "confidence,filter_response,base_data\n1,100.05,0.1,100.15,1,1,1,0.8,0.5 0.6,x\n";
  write(dir / "blinks.csv", blinks);
  GazeImportOptions none = frame_1000x500();
  none.blinks = "none";
  const auto kept_open = read_gaze(dir / "gaze_positions.csv", none);
  ASSERT_EQ(kept_open.size(), 3u);
  EXPECT_EQ(kept_open[1].state, EyeState::kOpen) << "--gaze-blinks none reads no blinks";

  test::ScratchDir elsewhere;
  write(elsewhere / "gaze_positions.csv", "gaze_timestamp,world_index,confidence,norm_pos_x,norm_pos_y,base_data\n"
                                          "100.00,0,0.9,0.5,0.5,x\n100.10,1,0.9,0.5,0.5,x\n");
  GazeImportOptions named = frame_1000x500();
  named.blinks = dir / "blinks.csv";
  const auto closed = read_gaze(elsewhere / "gaze_positions.csv", named);
  ASSERT_EQ(closed.size(), 2u);
  EXPECT_EQ(closed[1].state, EyeState::kClosed) << "the named blinks file is read";

  named.blinks = dir / "missing.csv";
  try {
    read_gaze(elsewhere / "gaze_positions.csv", named);
    ADD_FAILURE() << "a missing blinks file must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.csv"), std::string::npos) << e.what();
  }
}

// Options that do not apply to the log read are refused, not ignored; a
// blinks option may name the export's folder; malformed values name their line.
TEST(GazeExports, OptionsThatDoNotApplyAndMalformedValuesAreRefused) {
  test::ScratchDir dir;
  write(dir / "native.csv", "t,x,y\n0,1,1\n0.1,2,2\n");
  GazeImportOptions o = frame_1000x500();
  o.sync_message = "TRIAL_START";
  EXPECT_THROW(read_gaze(dir / "native.csv", o), UsageError) << "a message on a native log";
  o = frame_1000x500();
  o.recording = "rec-a";
  EXPECT_THROW(read_gaze(dir / "native.csv", o), UsageError) << "a recording on a native log";
  o = frame_1000x500();
  o.blinks = dir / "native.csv";
  EXPECT_THROW(read_gaze(dir / "native.csv", o), UsageError) << "blinks with a native log";
  const std::string asc = "MSG\t1000 DISPLAY_COORDS 0 0 999 499\nSTART\t1000 \tLEFT\tSAMPLES\tEVENTS\n"
                          "MSG\t1000 GO\n1000\t1.0\t2.0\t100.0\t...\n1001\tabc\t2.0\t100.0\t...\nEND\t1002\n";
  o = frame_1000x500();
  o.sync_message = "GO";
  o.sync_clock = 1.0;
  EXPECT_THROW(parse_gaze(asc, "s.asc", o), UsageError) << "two ways to set time 0";
  try {
    parse_gaze(asc, "s.asc", frame_1000x500());
    ADD_FAILURE() << "a sample position 'abc'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.asc:5: sample position 'abc'"), std::string::npos) << e.what();
  }
  const std::string tsv = "Recording timestamp [ms]\tRecording resolution width\tRecording resolution height\t"
                          "Gaze point X\tGaze point Y\n100\tabc\t1080\t1\t2\n";
  EXPECT_THROW(parse_gaze(tsv, "t.tsv", frame_1000x500()), InputError) << "Recording resolution 'abc'";
  // --gaze-blinks naming the export's folder reads its blinks.csv.
  test::ScratchDir core;
  write(core / "gaze_positions.csv", "gaze_timestamp,world_index,confidence,norm_pos_x,norm_pos_y,base_data\n"
                                     "100.00,0,0.9,0.5,0.5,x\n100.10,1,0.9,0.5,0.5,x\n");
  test::ScratchDir elsewhere;
  write(elsewhere / "blinks.csv", "id,start_timestamp,duration,end_timestamp,start_frame_index,index,end_frame_index,"
                                  "confidence,filter_response,base_data\n1,100.05,0.1,100.15,1,1,1,0.8,0.5 0.6,x\n");
  o = frame_1000x500();
  o.blinks = elsewhere.path().string();
  EXPECT_EQ(read_gaze(core / "gaze_positions.csv", o)[1].state, EyeState::kClosed);
}

// Pupil Cloud's Marker Mapper: the surface (the display watched) from its
// top left (0, 0) to its bottom right (1, 1); empty where it was not found.
const std::string kSurface =
    "section id,recording id,timestamp [ns],gaze detected on surface,gaze position on surface x [normalized],"
    "gaze position on surface y [normalized],fixation id,blink id\n"
    "s1,rec-a,2000000000,true,0.25,0.2,1,\n"
    "s1,rec-a,2005000000,false,1.1,0.5,,\n"
    "s1,rec-a,2010000000,false,,,,\n"
    "s1,rec-a,2015000000,true,0.5,0.5,,3\n"
    "s2,rec-b,9000000000,true,0.75,0.75,,\n";

TEST(GazeExports, NeonMarkerMapperSurfaceGazeIsTheDisplay) {
  ASSERT_EQ(detect_gaze_format(kSurface), GazeFormat::kNeonSurface);
  try {
    parse_gaze(kSurface, "gaze.csv", frame_1000x500());
    FAIL() << "two recordings and none chosen";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds 2 recordings (rec-a, rec-b)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--gaze-recording"), std::string::npos);
  }
  GazeImportOptions o = frame_1000x500();
  o.recording = "rec-a";
  const auto s = parse_gaze(kSurface, "gaze.csv", o);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_DOUBLE_EQ(s[0].x, 250.0);
  EXPECT_DOUBLE_EQ(s[0].y, 100.0) << "y from the top";
  EXPECT_EQ(s[1].state, EyeState::kOpen) << "off the surface, still where it looked";
  EXPECT_DOUBLE_EQ(s[1].x, 1100.0);
  EXPECT_EQ(s[2].state, EyeState::kLost) << "surface not found";
  EXPECT_EQ(s[3].state, EyeState::kClosed) << "a blink";
  o.recording = "rec-c";
  EXPECT_THROW(parse_gaze(kSurface, "gaze.csv", o), InputError);
}

TEST(GazeExports, TobiiTimestampsWithoutAUnitAndSeveralRecordings) {
  const std::string micro =
      "Recording timestamp\tGaze point X\tGaze point Y\tValidity left\tValidity right\n"
      "1000000\t100\t50\tValid\tValid\n1008333\t110\t60\tValid\tValid\n1016667\t120\t70\tValid\tValid\n";
  GazeRead read;
  auto s = parse_gaze(micro, "export.tsv", frame_1000x500(), &read);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_NEAR(s[2].t_s, 0.016667, 1e-9) << "microseconds";
  EXPECT_TRUE(mentions(read, "microseconds")) << (read.notes.empty() ? "" : read.notes[0]);
  const std::string milli =
      "Recording timestamp\tGaze point X\tGaze point Y\n1000\t100\t50\n1008,333\t110\t60\n1016,667\t120\t70\n";
  s = parse_gaze(milli, "export.tsv", frame_1000x500(), &read);
  EXPECT_NEAR(s[2].t_s, 0.016667, 1e-9) << "milliseconds (decimal commas)";
  const std::string two =
      "Recording name\tRecording timestamp [ms]\tGaze point X\tGaze point Y\n"
      "Recording1\t0\t1\t1\nRecording1\t10\t2\t2\nRecording2\t0\t3\t3\n";
  try {
    parse_gaze(two, "export.tsv", frame_1000x500());
    FAIL() << "two recordings";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Recording1, Recording2"), std::string::npos) << e.what();
  }
  GazeImportOptions o = frame_1000x500();
  o.recording = "Recording2";
  s = parse_gaze(two, "export.tsv", o);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_DOUBLE_EQ(s[0].x, 3.0);
}

// A binocular EyeLink file: "time xl yl pl xr yr pr"; the eyes averaged by
// default, either one on request.
const std::string kBinocular =
    "** CONVERTED FROM rec.edf using edfapi\n"
    "MSG\t1000 DISPLAY_COORDS 0 0 999 499\n"
    "START\t2000 \tLEFT\tRIGHT\tSAMPLES\tEVENTS\n"
    "2000\t  100.0\t  200.0\t 500.0\t  110.0\t  220.0\t 510.0\t.....\n"
    "2001\t    .\t    .\t    0.0\t  120.0\t  230.0\t 510.0\t.....\n"
    "END\t2002 \tSAMPLES\tEVENTS\tRES\t 30.0\t 30.0\n";

TEST(GazeExports, BinocularEyeLinkAveragesOrTakesOneEye) {
  GazeRead read;
  GazeImportOptions o = frame_1000x500();
  auto s = parse_gaze(kBinocular, "rec.asc", o, &read);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s[0].x, 105.0);
  EXPECT_DOUBLE_EQ(s[0].y, 210.0);
  EXPECT_DOUBLE_EQ(s[1].x, 120.0) << "the right eye where the left is missing";
  EXPECT_TRUE(mentions(read, "binocular, the two eyes averaged"));
  o.eye = "left";
  s = parse_gaze(kBinocular, "rec.asc", o);
  EXPECT_DOUBLE_EQ(s[0].x, 100.0);
  EXPECT_EQ(s[1].state, EyeState::kLost);
  o.eye = "right";
  s = parse_gaze(kBinocular, "rec.asc", o);
  EXPECT_DOUBLE_EQ(s[0].y, 220.0);
}

// Windows tools write a byte-order mark and CRLF: every format reads the
// same samples with them as without.
TEST(GazeExports, AByteOrderMarkAndCrlfAreAcceptedInEveryFormat) {
  const std::string native = "t,x,y\n0,10,20\n0.5,30,40\n";
  const std::string tobii = "Recording timestamp [ms]\tGaze point X\tGaze point Y\n0\t1\t2\n10\t3\t4\n";
  const std::vector<std::string> texts = {native, kOldPupilPlayer, kNeonHeader + "s,r,1000,1,2,1,,,0,0\n",
                                          tobii, kBinocular};
  for (const std::string& text : texts) {
    std::string windows = "\xEF\xBB\xBF";
    for (char c : text) windows += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const auto plain = parse_gaze(text, "log", frame_1000x500());
    const auto crlf = parse_gaze(windows, "log", frame_1000x500());
    ASSERT_EQ(plain.size(), crlf.size()) << text.substr(0, 30);
    for (size_t i = 0; i < plain.size(); ++i) {
      EXPECT_EQ(plain[i].t_s, crlf[i].t_s);
      EXPECT_EQ(plain[i].x, crlf[i].x);
      EXPECT_EQ(plain[i].state, crlf[i].state);
    }
  }
}

}  // namespace
}  // namespace eyestream::io
