#include "pipeline/run/run_inputs.hpp"

#include "io/source_factory.hpp"

namespace eyestream::pipeline {

io::GazeImportOptions gaze_import_options(const Settings& s, const io::SourceInfo& info) {
  io::GazeImportOptions o;
  const std::string& f = s.gaze_format;
  o.format = f == "native"       ? io::GazeFormat::kNative
             : f == "pupil-core" ? io::GazeFormat::kPupilCore
             : f == "neon"       ? io::GazeFormat::kNeon
             : f == "neon-surface" ? io::GazeFormat::kNeonSurface
             : f == "tobii"      ? io::GazeFormat::kTobii
             : f == "eyelink"    ? io::GazeFormat::kEyeLink
                                 : io::GazeFormat::kAuto;
  o.units = s.gaze_units == "norm" ? io::GazeUnits::kNormalised : io::GazeUnits::kPixels;
  o.frame_width = info.width;
  o.frame_height = info.height;
  o.source_width = s.gaze_source_width;
  o.source_height = s.gaze_source_height;
  o.min_confidence = s.gaze_confidence;
  o.offset_s = s.gaze_offset_s;
  o.sync_clock = s.gaze_sync_s;
  o.sync_message = s.gaze_sync_message;
  o.recording = s.gaze_recording;
  o.blinks = s.gaze_blinks;
  o.pupils = s.gaze_pupils;
  o.want_pupils = s.pupil_from_gaze;
  o.eye = s.gaze_eye;
  o.pupil_scale_mm = s.gaze_pupil_scale_mm;
  return o;
}

std::unique_ptr<io::FrameSource> open_input(const Settings& s) {
  return io::open_source(s.input, io::SourceOptions{s.exr, s.video_input, s.frame_size});
}

}  // namespace eyestream::pipeline
