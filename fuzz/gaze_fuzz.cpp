// libFuzzer target: every gaze log reader. The first byte picks the format
// and units, and with bit 0x40 the rest holds the log, a form feed, and a
// Pupil Labs pupil file read beside it (pupil_positions.csv or
// 3d_eye_states.csv); else the rest is the log. Malformed input must end in
// InputError or UsageError, never in a crash or another exception.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/error.hpp"
#include "io/gaze_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  using eyestream::io::GazeFormat;
  const GazeFormat formats[] = {GazeFormat::kAuto,  GazeFormat::kNative, GazeFormat::kPupilCore,
                                GazeFormat::kNeon, GazeFormat::kTobii,  GazeFormat::kEyeLink};
  eyestream::io::GazeImportOptions o;
  o.format = formats[data[0] % 6];
  o.units = data[0] & 0x80 ? eyestream::io::GazeUnits::kNormalised : eyestream::io::GazeUnits::kPixels;
  o.frame_width = 640;
  o.frame_height = 360;
  std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  const size_t split = text.find('\f');
  if (data[0] & 0x40 && split != std::string::npos) {
    o.pupils_text = text.substr(split + 1);
    o.pupils_name = "pupils.csv";
    o.want_pupils = true;
    text.resize(split);
  }
  try {
    eyestream::io::parse_gaze(text, "fuzz.csv", o);
  } catch (const eyestream::InputError&) {
  } catch (const eyestream::UsageError&) {
  }
  return 0;
}
