// Gaze logs from eye-tracker exports, mapped to the native model (time from
// the first frame, position in input-frame pixels, open/closed/lost).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/gaze_csv.hpp"
#include "io/gaze_sample.hpp"

namespace eyestream::io {

enum class GazeFormat { kAuto, kNative, kPupilCore, kNeon, kNeonSurface, kTobii, kEyeLink };

struct GazeImportOptions {
  GazeFormat format = GazeFormat::kAuto;
  GazeUnits units = GazeUnits::kPixels;  // native format only
  int frame_width = 0, frame_height = 0;
  // The export's own coordinate frame (scene camera or screen) in pixels,
  // scaled to the input frame; 0: the format's default or the file's own
  // (Neon 1600x1200; EyeLink from DISPLAY_COORDS; Tobii and native: the frame).
  int source_width = 0, source_height = 0;
  double min_confidence = 0.6;       // Pupil Core: lower confidence is "lost"
  double offset_s = 0.0;             // added to every time after alignment
  std::optional<double> sync_clock;  // export clock (its own unit, seconds) at frame 0; default the first sample
  std::string sync_message;          // EyeLink: the first MSG line holding this text is frame 0
  // An export holding several recordings (Neon, Tobii) is refused naming
  // them unless this names the one to read.
  std::string recording;
  std::string eye = "average";  // EyeLink binocular files: left, right or average
  // EyeLink: millimetres per unit of the samples' pupil diameter, or per
  // square root of a unit of pupil area (files whose "PUPIL AREA" line, or
  // no PUPIL line, says they hold areas); 0: the pupil is not read.
  double pupil_scale_mm = 0.0;
  // Pupil Core and Neon blinks: "auto" reads the blinks.csv beside the
  // export when it is there, "none" reads none, anything else is the path
  // of the blinks file (an InputError when it cannot be read).
  std::string blinks = "auto";
  // The blinks read (read_gaze fills these); they close the eye.
  std::string blinks_text, blinks_name;
  // Pupil Core and Neon pupil diameters, read only when `want_pupils`:
  // "auto" reads the pupil_positions.csv (Core) or 3d_eye_states.csv
  // (Neon) beside the export, "none" none, anything else is the path of
  // one (or the export's folder).
  std::string pupils = "auto";
  bool want_pupils = false;
  std::string pupils_text, pupils_name;  // what read_gaze read
};

// What a read found beyond the samples: the format, and what it assumed or
// took from elsewhere ("Tobii timestamps without a unit: microseconds, from
// their spacing"), for the run's gaze summary.
struct GazeRead {
  GazeFormat format = GazeFormat::kAuto;
  std::vector<std::string> notes;
};

// Reads `path` in the given or detected format. Exports whose clock is
// absolute (all but native) are aligned so `sync_clock` (default: the first
// sample) is time 0; then offset_s is added. Export samples are ordered by
// time; of samples at the same time the last is kept. Malformed lines are
// an InputError naming the file and line.
// A UTF-8 byte-order mark and CRLF line ends are accepted in every format.
// `read`, when given, receives the format read (the detected one for
// kAuto) and the notes.
std::vector<GazeSample> read_gaze(const std::string& path, const GazeImportOptions& options, GazeRead* read = nullptr);

// The same for text in memory; `name` stands for the file in messages.
std::vector<GazeSample> parse_gaze(const std::string& text, const std::string& name, const GazeImportOptions& options,
                                   GazeRead* read = nullptr);

// The format the text's header looks like (kNative when unsure).
GazeFormat detect_gaze_format(const std::string& text);

// Sets `s` to the position (x sx, y sy) when `seen`, else marks it lost.
inline void place(GazeSample& s, bool seen, double x, double y, double sx, double sy) {
  if (!seen) {
    s.state = EyeState::kLost;
    return;
  }
  s.x = x * sx;
  s.y = y * sy;
}

// Per-format parsers: samples with the export's own clock in seconds;
// what they assume goes to `notes`.
using GazeNotes = std::vector<std::string>;
std::vector<GazeSample> parse_pupil_core(const std::string& text, const std::string& name, const GazeImportOptions& o,
                                         GazeNotes& notes);
std::vector<GazeSample> parse_neon(const std::string& text, const std::string& name, const GazeImportOptions& o,
                                   GazeNotes& notes);
std::vector<GazeSample> parse_neon_surface(const std::string& text, const std::string& name,
                                           const GazeImportOptions& o, GazeNotes& notes);
std::vector<GazeSample> parse_tobii(const std::string& text, const std::string& name, const GazeImportOptions& o,
                                    GazeNotes& notes);
// `sync_s` receives the time of the first MSG holding o.sync_message.
std::vector<GazeSample> parse_eyelink(const std::string& text, const std::string& name, const GazeImportOptions& o,
                                      GazeNotes& notes, std::optional<double>* sync_s = nullptr);

// Keeps the rows of one recording of a table whose `column` (-1: none)
// names recordings: the one `choice` names, or the only one; several and
// no choice (or a choice not there) is an InputError naming them.
struct DelimitedTable;
void keep_recording(DelimitedTable& t, int column, const std::string& choice, const std::string& name,
                    GazeNotes& notes);

// Marks the samples inside the blinks of a Pupil Core or Neon blinks.csv
// (export clock) closed; returns how many blinks it holds.
size_t apply_blinks(const std::string& text, const std::string& name, const std::string& recording,
                    std::vector<GazeSample>& samples);

// Gives the samples (export clock) the pupil diameter of a Pupil Core
// pupil_positions.csv (diameter_3d of the 3d model's rows with confidence
// at least o.min_confidence; eye1 the left eye, eye0 the right) or a Neon
// 3d_eye_states.csv (pupil diameter left/right [mm]), interpolated
// linearly between its samples at most 1 s apart, the eyes averaged
// (o.eye: left, right or average); NaN elsewhere (a blink, low confidence,
// a diameter outside 1-10 mm of an eye read: noted), which the gaze
// timeline bridges. A Neon file holding several recordings is read for
// o.recording (parse_gaze passes the gaze log's own unless
// --gaze-recording chose one). Returns how many samples got one; a file
// without rows is an InputError naming it.
size_t apply_pupils(const std::string& text, const std::string& name, const GazeImportOptions& o,
                    std::vector<GazeSample>& samples, GazeNotes& notes);

}  // namespace eyestream::io
