// libFuzzer target: every gaze log reader. The first byte picks the format
// and units; the rest is the file. Malformed input must end in InputError
// or UsageError, never in a crash or another exception.
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
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    eyestream::io::parse_gaze(text, "fuzz.csv", o);
  } catch (const eyestream::InputError&) {
  } catch (const eyestream::UsageError&) {
  }
  return 0;
}
