// What the command line needs of an eyestream::Eye beyond the public API
// (not installed). Its run and bench drive their eyes through here, so
// the program is the API's client: one path through the model.
#pragma once

#include <memory>

#include "eyestream/eye.hpp"
#include "io/frame.hpp"
#include "io/frame_source.hpp"
#include "pipeline/eye/eye_simulator.hpp"
#include "pipeline/eye/gaze_timeline.hpp"
#include "pipeline/settings/plan.hpp"
#include "pipeline/settings/settings.hpp"

namespace eyestream::detail {

// Hidden: libeyestream.so does not export it.
struct __attribute__((visibility("hidden"))) EyeAccess {
  // An eye of settings already compiled (one panel of a run) for the
  // source's frames. Throws the command line's own errors.
  static Eye make(const pipeline::Settings& settings, const io::SourceInfo& source);
  // Eye::set_gaze with the gaze log's timeline (one for every panel).
  static void set_gaze(Eye& eye, std::shared_ptr<const pipeline::GazeTimeline> recording);
  // The source's frame at its own index and time, seen until t1_s; the
  // display-linear image, not encoded. report() then holds its report.
  // A frame moved in is let go of after the glare (EyeSimulator::process).
  static io::DisplayFrame process(Eye& eye, io::SceneFrame frame, double t1_s);
  static const pipeline::FrameReport& report(const Eye& eye);
  static const pipeline::Plan& plan(const Eye& eye);
  static const pipeline::EyeSimulator& simulator(const Eye& eye);
  // The checkpoint's view of the state (restore checks it first).
  static void restore(Eye& eye, const pipeline::EyeMemory& memory);
};

}  // namespace eyestream::detail
