// Eye-tracker exports, each from a small fixture written from the
// format's documented header.
#include "io/gaze_import.hpp"

#include <gtest/gtest.h>

#include "tests/gaze_options.hpp"

#include "io/error.hpp"

namespace eyestream::io {
namespace {

using test::frame_1000x500;

TEST(GazeImport, PupilCoreNormalisedBottomLeftWithConfidence) {
  const std::string text =
      "gaze_timestamp,world_index,confidence,norm_pos_x,norm_pos_y,base_data\n"
      "3401.250,0,0.95,0.5,0.25,x\n"
      "3401.258,0,0.30,0.6,0.6,x\n"  // low confidence: lost
      "3401.266,1,0.90,0.1,0.9,x\n";
  ASSERT_EQ(detect_gaze_format(text), GazeFormat::kPupilCore);
  const auto s = parse_gaze(text, "gaze_positions.csv", frame_1000x500());
  ASSERT_EQ(s.size(), 3u);
  EXPECT_NEAR(s[0].t_s, 0.0, 1e-9) << "the first sample is frame 0";
  EXPECT_NEAR(s[2].t_s, 0.016, 1e-9);
  EXPECT_DOUBLE_EQ(s[0].x, 500.0);
  EXPECT_DOUBLE_EQ(s[0].y, 375.0) << "origin bottom-left";
  EXPECT_EQ(s[1].state, EyeState::kLost);
  EXPECT_DOUBLE_EQ(s[2].y, 50.0);
}

TEST(GazeImport, NeonPixelsBlinksAndWorn) {
  const std::string text =
      "section id,recording id,timestamp [ns],gaze x [px],gaze y [px],worn,fixation id,blink id,azimuth [deg],"
      "elevation [deg]\n"
      "a,b,1700000000000000000,800,600,1,1,,0,0\n"
      "a,b,1700000000005000000,800,600,1,,7,0,0\n"
      "a,b,1700000000010000000,400,300,0,,,0,0\n"
      "a,b,1700000000015000000,1600,1200,1,2,,0,0\n";
  ASSERT_EQ(detect_gaze_format(text), GazeFormat::kNeon);
  const auto s = parse_gaze(text, "gaze.csv", frame_1000x500());
  ASSERT_EQ(s.size(), 4u);
  EXPECT_NEAR(s[1].t_s, 0.005, 1e-6);
  EXPECT_DOUBLE_EQ(s[0].x, 500.0) << "1600x1200 scene camera scaled to the frame";
  EXPECT_DOUBLE_EQ(s[0].y, 250.0);
  EXPECT_EQ(s[1].state, EyeState::kClosed) << "blink id";
  EXPECT_EQ(s[2].state, EyeState::kLost) << "not worn";
  EXPECT_DOUBLE_EQ(s[3].x, 1000.0);
}

TEST(GazeImport, TobiiMicrosecondsDecimalCommasAndValidity) {
  const std::string text =
      "Recording timestamp [\xce\xbcs]\tGaze point X\tGaze point Y\tValidity left\tValidity right\n"
      "2000000\t960,5\t540\tValid\tValid\n"
      "2008333\t\t\tInvalid\tInvalid\n"
      "2016666\t100\t50\tInvalid\tValid\n";
  ASSERT_EQ(detect_gaze_format(text), GazeFormat::kTobii);
  GazeImportOptions o = frame_1000x500();
  o.source_width = 1920;
  o.source_height = 1080;
  const auto s = parse_gaze(text, "export.tsv", o);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_NEAR(s[1].t_s, 0.008333, 1e-9);
  EXPECT_NEAR(s[0].x, 960.5 * 1000 / 1920, 1e-9) << "decimal comma";
  EXPECT_EQ(s[1].state, EyeState::kLost);
  EXPECT_EQ(s[2].state, EyeState::kOpen) << "one valid eye is enough";
}

// Tobii Pro Lab exports name the screen: "Recording resolution width/height".
TEST(GazeImport, TobiiTakesTheScreenFromRecordingResolution) {
  const std::string text =
      "Recording timestamp [ms]\tRecording resolution height\tRecording resolution width\tGaze point X\tGaze point Y\n"
      "100\t1200\t1920\t960\t600\n150\t1200\t1920\t1920\t0\n";
  GazeRead read;
  const auto s = parse_gaze(text, "export.tsv", frame_1000x500(), &read);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s[0].x, 500.0) << "the 1920x1200 screen's centre is the frame's";
  EXPECT_DOUBLE_EQ(s[0].y, 250.0);
  EXPECT_DOUBLE_EQ(s[1].x, 1000.0);
  ASSERT_FALSE(read.notes.empty());
  EXPECT_NE(read.notes.back().find("1920x1200"), std::string::npos) << read.notes.back();
}

// A bare "MSG" line (found by the gaze fuzzer, which read past the line's
// words) is skipped like any other message.
TEST(GazeImport, EyeLinkBareMessageLinesAreSkipped) {
  const std::string asc = "** CONVERTED FROM x.EDF\nMSG\nMSG\t1000 DISPLAY_COORDS 0 0 999 499\n"
                          "START\t1000 \tLEFT\tSAMPLES\n1000\t10.0\t20.0\t100.0\t...\nMSG\nEND\t1001\n";
  GazeImportOptions o = frame_1000x500();
  EXPECT_EQ(parse_gaze(asc, "bare.asc", o).size(), 1u);
  o.sync_message = "GO";
  EXPECT_THROW(parse_gaze(asc, "bare.asc", o), InputError) << "no MSG holds GO";
}

// Without DISPLAY_COORDS, the tracker's GAZE_COORDS gives the screen.
TEST(GazeImport, EyeLinkGazeCoordsGiveTheScreenWithoutDisplayCoords) {
  const std::string asc = "MSG\t1000 GAZE_COORDS 0.00 0.00 1999.00 999.00\nSTART\t1000 \tLEFT\tSAMPLES\n"
                          "1000\t1000.0\t500.0\t100.0\t...\nEND\t1001\n";
  const auto s = parse_gaze(asc, "g.asc", frame_1000x500());
  ASSERT_EQ(s.size(), 1u);
  EXPECT_DOUBLE_EQ(s[0].x, 500.0) << "the 2000x1000 screen's centre";
  EXPECT_DOUBLE_EQ(s[0].y, 250.0);
}

TEST(GazeImport, TobiiMillisecondsByDefault) {
  const std::string text = "Recording timestamp\tGaze point X\tGaze point Y\n100\t1\t2\n150\t3\t4\n";
  const auto s = parse_gaze(text, "export.tsv", frame_1000x500());
  EXPECT_NEAR(s[1].t_s, 0.05, 1e-12);
}

TEST(GazeImport, EyeLinkSamplesMissingValuesAndBlinks) {
  const std::string text =
      "** CONVERTED FROM test.edf\n"
      "MSG\t1000 DISPLAY_COORDS 0 0 1999 999\n"
      "START\t1000 \tLEFT\tSAMPLES\tEVENTS\n"
      "1000\t1000.0\t500.0\t1200.0\t...\n"
      "1002\t   .\t   .\t    0.0\t...\n"
      "SBLINK L 1004\n"
      "1004\t   .\t   .\t    0.0\t...\n"
      "EBLINK L 1004 1010 7\n"
      "1012\t200.0\t100.0\t1100.0\t...\n";
  ASSERT_EQ(detect_gaze_format(text), GazeFormat::kEyeLink);
  const auto s = parse_gaze(text, "run.asc", frame_1000x500());
  ASSERT_EQ(s.size(), 4u) << "the blink start and its sample share a time: one is kept";
  EXPECT_DOUBLE_EQ(s[0].x, 500.0) << "2000x1000 screen scaled to the frame";
  EXPECT_EQ(s[1].state, EyeState::kLost);
  EXPECT_EQ(s[2].state, EyeState::kClosed);
  EXPECT_NEAR(s[3].t_s, 0.012, 1e-12);
  EXPECT_DOUBLE_EQ(s[3].y, 50.0);
}

// The structure of real edf2asc output: a header, a calibration block whose
// values continue on indented lines (numbers with trailing commas), the
// recording block between START and END, 2 kHz fractional times, and a
// stimulus-onset message to sync on.
const char* kRealAsc =
    "** CONVERTED FROM D:\\data\\s01.edf using edfapi 4.2 Jan 15 2020\n"
    "** DATE: Tue Mar  3 10:12:44 2020\n"
    "**\n"
    "\n"
    "MSG\t645210 !CAL \n"
    ">>>>>>> CALIBRATION (HV9,P-CR) FOR LEFT: <<<<<<<<<\n"
    "MSG\t645210 !CAL Calibration points:  \n"
    "MSG\t645210 !CAL -10.9, -36.8         0,      0 \n"
    "MSG\t645210 !CAL eye check box: (L,R,T,B)\n"
    "\t   -41     26    -51     -0\n"
    "MSG\t645210 !CAL href cal range: (L,R,T,B)\n"
    "\t-5220   5220  -3915   3915\n"
    "MSG\t645210 !CAL Cal coeff:(X=a+bx+cy+dxx+eyy,Y=f+gx+goaly+ixx+jyy)\n"
    "   9.5364e-06,  0.1295,  0.0015, -0.00014,  2.1e-05 \n"
    "   4.2e-05,  0.0031,  0.14,  3.3e-05, -0.00011 \n"
    "MSG\t645211 DISPLAY_COORDS 0 0 1919 1079\n"
    "1280000.0\t  0.1\t 33.5\t 1000.0\t...\n"
    "START\t1288000 \tLEFT\tSAMPLES\tEVENTS\n"
    "PRESCALER\t1\n"
    "MSG\t1288010 TRIAL_START stimulus onset\n"
    "1288000.0\t 100.0\t 200.0\t 1100.0\t...\n"
    "1288000.5\t 101.0\t 201.0\t 1100.0\t...\n"
    "1288010.0\t 960.0\t 540.0\t 1100.0\t...\n"
    "1288010.5\t 962.0\t 541.0\t 1100.0\t...\n"
    "END\t1288011 \tSAMPLES\tEVENTS\tRES\t38.4\t35.9\n"
    "1290000.0\t 5.0\t 5.0\t 1000.0\t...\n";

TEST(GazeImport, RealEyeLinkStructureCalibrationBlocksAndAMessageToSyncOn) {
  GazeImportOptions o = frame_1000x500();
  ASSERT_EQ(detect_gaze_format(kRealAsc), GazeFormat::kEyeLink);
  const auto s = parse_gaze(kRealAsc, "s01.asc", o);
  ASSERT_EQ(s.size(), 4u) << "only the recording block's samples; no calibration line, none outside START-END";
  EXPECT_DOUBLE_EQ(s[0].t_s, 0.0) << "time 0 is the block's first sample, not a calibration line";
  EXPECT_NEAR(s[1].t_s, 0.0005, 1e-12) << "2 kHz: fractional milliseconds";
  EXPECT_NEAR(s[2].x, 960.0 * 1000 / 1920, 1e-9) << "DISPLAY_COORDS 1920x1080 scaled to the 1000x500 frame";
  o.sync_message = "TRIAL_START";
  const auto synced = parse_gaze(kRealAsc, "s01.asc", o);
  EXPECT_NEAR(synced[2].t_s, 0.0, 1e-12) << "the TRIAL_START message is frame 0";
  EXPECT_NEAR(synced[0].t_s, -0.010, 1e-12);
  // Experiment Builder's offset form: logged 10 ms after its event, which is at 1288010 - 10.
  std::string offset_form = kRealAsc;
  const std::string plain = "MSG\t1288010 TRIAL_START";
  offset_form.replace(offset_form.find(plain), plain.size(), "MSG\t1288010 10 TRIAL_START");
  const auto early = parse_gaze(offset_form, "s01.asc", o);
  EXPECT_NEAR(early[2].t_s, 0.010, 1e-12) << "MSG time offset: the onset is at time - offset";
  // A file recording only the left eye, asked for the right: refused.
  GazeImportOptions right = o;
  right.sync_message.clear();
  right.eye = "right";
  EXPECT_THROW(parse_gaze(kRealAsc, "s01.asc", right), UsageError);
  right.eye = "left";
  EXPECT_EQ(parse_gaze(kRealAsc, "s01.asc", right).size(), 4u);
  o.sync_message = "NO_SUCH_MESSAGE";
  try {
    parse_gaze(kRealAsc, "s01.asc", o);
    FAIL() << "a missing sync message must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s01.asc: no MSG line contains 'NO_SUCH_MESSAGE'"), std::string::npos)
        << e.what();
  }
}

TEST(GazeImport, EyeLinkWithoutDisplayCoordsNeedsTheScreenSize) {
  const std::string text = "START\t1000 \tLEFT\tSAMPLES\n1000\t100.0\t50.0\t900.0\t...\nEND\t1001\n";
  GazeImportOptions o = frame_1000x500();
  try {
    parse_gaze(text, "bare.asc", o);
    FAIL() << "unmappable coordinates must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--gaze-source-width"), std::string::npos) << e.what();
  }
  o.source_width = 2000, o.source_height = 1000;
  EXPECT_DOUBLE_EQ(parse_gaze(text, "bare.asc", o)[0].x, 50.0);
}

TEST(GazeImport, SyncAndOffsetAlignTheClock) {
  const std::string text = "gaze_timestamp,confidence,norm_pos_x,norm_pos_y\n10.0,1,0.5,0.5\n10.5,1,0.5,0.5\n";
  GazeImportOptions o = frame_1000x500();
  o.sync_clock = 9.0;
  o.offset_s = 0.25;
  const auto s = parse_gaze(text, "g.csv", o);
  EXPECT_NEAR(s[0].t_s, 1.25, 1e-12);
  EXPECT_NEAR(s[1].t_s, 1.75, 1e-12);
}

TEST(GazeImport, BadLinesNameFileAndLine) {
  const std::string text = "gaze_timestamp,confidence,norm_pos_x,norm_pos_y\n10.0,1,0.5,0.5\nten,1,0.5,0.5\n";
  try {
    parse_gaze(text, "g.csv", frame_1000x500());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("g.csv:3"), std::string::npos) << e.what();
  }
}

TEST(GazeImport, NativeLogsStillParseAndTakeTheOffset) {
  GazeImportOptions o = frame_1000x500();
  o.offset_s = 1.0;
  const auto s = parse_gaze("t,x,y\n0,1,2\n", "g.csv", o);
  EXPECT_DOUBLE_EQ(s[0].t_s, 1.0);
}

}  // namespace
}  // namespace eyestream::io
