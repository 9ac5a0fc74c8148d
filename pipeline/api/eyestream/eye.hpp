// eyestream as a library: one viewer's eye, compiled once from the same
// parameter table the command line uses, then fed frame by frame (the
// OpenColorIO idea: a config compiled into a processor applied to many
// images). The command line's model path is the one used here: no second
// path through the model.
//
//   eyestream::Eye eye(1920, 1080, 60.0, {{"quality", "fast"}, {"viewer-age", "70"}});
//   eyestream::Frame out = eye.process(rgb_cd_m2, {{t, x, y}});   // out.linear, out.code, out.report
//
// Errors are eyestream::Error carrying the command line's one-line message.
#pragma once

#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace eyestream {

namespace detail {
struct EyeAccess;  // the command line's access (not installed)
}

// An error with the message the command line prints after "eyestream:
// error:" and its exit code (2 usage, 3 input, 4 output).
class Error : public std::runtime_error {
 public:
  Error(const std::string& message, int exit_code) : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

// A gaze sample: seconds from the first frame, frame pixels (origin at the
// top-left corner), whether the eye is closed (a blink: darkness, the last
// position held) or the tracker lost it (the last position held, open).
struct Gaze {
  double t_s = 0.0, x = 0.0, y = 0.0;
  bool closed = false;
  bool lost = false;
  // The pupil diameter the tracker recorded (mm); NaN when none. With the
  // setting "pupil-from-gaze" it drives the optics, held across frames
  // without one.
  double pupil_mm = std::numeric_limits<double>::quiet_NaN();
};

// What happened to one frame.
struct FrameReport {
  double adaptation_cd_m2 = 0.0;
  double pupil_mm = 0.0;        // the optics' pupil: the recorded one ("pupil-from-gaze") or the model's
  double pupil_model_mm = 0.0;  // the model's, which follows the field luminance
  double gaze_x = 0.0, gaze_y = 0.0;
  bool eye_closed = false;
  bool glare = false, retina = false, mesopic = false, afterimages = false;  // which stages worked
  // With the setting "report" = "true" (as the command line's --report):
  // the brightest scene luminance, the veiling luminance at the gaze and
  // the threshold increment it causes (CIE 1999, as in the report's CSV);
  // -1 when not asked for or unknown (eyes closed, a PSF without a veil).
  double peak_cd_m2 = -1.0;
  double veil_cd_m2 = -1.0;
  double ti_percent = -1.0;
  // With "report" and a target ("target" X,Y,W,H or "target-mask"): the
  // mean scene luminance over the target and over its surround, and the
  // veiling luminance at its centroid; -1 when unknown.
  double target_cd_m2 = -1.0, background_cd_m2 = -1.0, target_veil_cd_m2 = -1.0;
  // NaN or infinite input pixels (seen as black; never in the state).
  long long nonfinite_pixels = 0;
  // The model's time for the frame by stage, ms (encoding not included).
  double glare_ms = 0.0, adaptation_ms = 0.0, retina_ms = 0.0, mesopic_ms = 0.0, afterimage_ms = 0.0;
};

struct Frame {
  cv::Mat linear;  // display-linear RGB, CV_32FC3, 1 = the display's peak
  cv::Mat code;    // encoded and dithered RGB, CV_8UC3 (or CV_16UC3 with "png-bits" 16)
  FrameReport report;
};

class Eye {
 public:
  // A width x height stream at fps frames/s. `settings` maps parameter
  // names to values as on the command line ("viewer-age" -> "70"; "_" may
  // stand for "-"), "quality" choosing the preset the others override.
  Eye(int width, int height, double fps, const std::map<std::string, std::string>& settings = {});
  ~Eye();
  Eye(Eye&&) noexcept;
  Eye& operator=(Eye&&) noexcept;

  // The next frame: linear Rec.709 RGB in cd/m^2 (CV_32FC3, width x
  // height) and the gaze samples inside its interval [n / fps, (n + 1) /
  // fps). Without samples the last gaze holds, as on the command line;
  // before the first sample the gaze is at the frame's centre (the command
  // line, reading the whole log, holds the first sample back to frame 0:
  // set_gaze does the same).
  Frame process(const cv::Mat& rgb_cd_m2, const std::vector<Gaze>& gaze = {});
  // The same for a plain pointer: height rows of width x 3 floats, rows
  // `stride_bytes` apart (not copied).
  Frame process(const float* rgb_cd_m2, std::size_t stride_bytes, const std::vector<Gaze>& gaze = {});

  // The whole gaze recording at once, as the command line reads a log:
  // every frame then takes its gaze from it (the first sample held back to
  // frame 0, recorded pupils interpolated across blinks and gaps), and
  // process() refuses samples of its own. An empty recording goes back to
  // samples given frame by frame, the gaze at the frame's centre until the
  // first. Nothing changes when it throws (a non-finite sample).
  void set_gaze(const std::vector<Gaze>& recording);

  // The eye's state between frames (the checkpoint's contents, a copy), to
  // resume. A recording given with set_gaze is not part of it: give the
  // restoring eye the same recording.
  struct State {
    std::vector<cv::Mat> mats;
    std::vector<double> numbers;
  };
  State state() const;
  void restore(const State& state);

  // The resolved settings, one "name = value" line each.
  std::string describe() const;
  int width() const;
  int height() const;
  double fps() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  explicit Eye(std::unique_ptr<Impl> impl);
  friend struct detail::EyeAccess;
};

// The viewer's point-spread function as the glare stage uses it (the
// command line's `eyestream psf`): for a width x height frame seen under
// `settings` (viewer, viewing condition, "psf-model", ...) by an eye
// adapted to adaptation_cd_m2. The kernel is R, G, B (CV_32FC3) of
// (2 height - 1) rows and (2 width - 1) columns, centred on (width - 1,
// height - 1); each channel sums to the share of a pixel's light spread
// within the frame's reach.
struct Psf {
  cv::Mat kernel;
  double pixels_per_degree = 0.0;  // the frame's scale at its centre
  double pupil_mm = 0.0;           // the pupil at that adaptation
};
Psf psf(int width, int height, double adaptation_cd_m2, const std::map<std::string, std::string>& settings = {});

}  // namespace eyestream
