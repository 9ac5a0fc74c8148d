// The viewer's eye over time: owns every piece of temporal state and turns
// each scene frame (with the gaze during its interval) into a display frame.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "io/frame.hpp"
#include "pipeline/eye/gaze_timeline.hpp"
#include "pipeline/eye/glare_stage.hpp"
#include "pipeline/eye/mesopic_stage.hpp"
#include "pipeline/settings/plan.hpp"
#include "pipeline/eye/retina_stage.hpp"
#include "pipeline/eye/stage_activity.hpp"
#include "pipeline/eye/target_region.hpp"
#include "retina/luminance_field.hpp"

namespace eyestream::pipeline {

// What happened to one frame, for logs and reports.
struct FrameReport {
  double adaptation_log = 0.0;  // at the end of the interval, log10 cd/m^2
  double target_log = 0.0;      // the last adaptation target
  double gaze_x = 0.0, gaze_y = 0.0;
  bool eye_closed = false;
  std::int64_t nonfinite_pixels = 0;
  StageActivity active;    // which stages worked on this frame (glare: false when nothing exceeded the display peak)
  StageTimes times;        // and how long each took
  // Filled when the plan asks for a report:
  double pupil_mm = 0.0;     // the optics' pupil: the recorded one (--pupil-from-gaze) or the model's
  double pupil_model_mm = 0.0;      // the model's, at the end of the interval (it follows the field luminance)
  double pupil_recorded_mm = -1.0;  // the gaze log's for the frame, bridged across blinks; -1 without one
  double peak_cd_m2 = 0.0;   // brightest scene pixel (photopic luminance)
  double veil_cd_m2 = -1.0;  // veiling luminance at the gaze; -1 without a Vos PSF or with eyes closed
  double ti_percent = -1.0;  // threshold increment at the gaze; -1 when the veil is unknown
  // Filled when the report is on and the frame has a target (target_region.hpp):
  double target_cd_m2 = -1.0;        // mean scene luminance over the target; -1 without one
  double background_cd_m2 = -1.0;    // mean over its surround
  double target_veil_cd_m2 = -1.0;   // veiling luminance at the target's centroid; -1 when unknown
};

// Everything an EyeSimulator carries from frame to frame (checkpoints);
// the optics and mesopic stages keep no state of their own.
struct EyeMemory {
  std::optional<double> adaptation_log;
  std::optional<double> pupil_mm;
  bool retina_started = false;
  std::vector<cv::Mat> retina;
};

class EyeSimulator {
 public:
  explicit EyeSimulator(Plan plan);

  // Steps the state through the frame's interval, one exact step per gaze
  // segment (global adaptation) or group of nearby segments (retina
  // state), and renders what the eye sees at the end of the interval:
  // darkness while the eye is closed, with any afterimages on top. On the first frame the viewer starts
  // adapted to the scene at the first gaze point (even in a blink: the
  // viewer was looking at it before). Non-finite pixels are counted and
  // seen as black; they never enter the state.
  // Returns DisplayFrame::linear; encoding is the caller's (preview.hpp).
  // `target_mask` (CV_8U, may be empty) marks the target the report measures.
  // The frame is taken by value: once the glare has made the retinal image,
  // the eye lets go of the scene (unless the report measures it), so a
  // caller that hands over its only reference (std::move) frees the
  // scene's memory for the rest of the frame's stages.
  io::DisplayFrame process(io::SceneFrame frame, const std::vector<GazeSegment>& segments,
                           FrameReport* report = nullptr, const cv::Mat& target_mask = cv::Mat());

  double adaptation_log() const { return adaptation_.value_or(plan_.dark_log); }
  std::optional<double> pupil_mm() const { return pupil_; }  // the model's, as save() gives it
  EyeMemory save() const;
  // restore() takes what save() gave; memory_error() says what is wrong
  // with a memory from elsewhere (a checkpoint file), empty when nothing.
  void restore(const EyeMemory& memory);
  std::string memory_error(const EyeMemory& memory) const;
  const RetinaStage& retina() const { return *retina_; }
  const GlareStage* glare() const { return glare_.get(); }

 private:
  // recorded_pupil_mm: the frame's recorded pupil the optics took, or NaN.
  void fill_glare_report(const cv::Mat& scene, const GazeSegment& gaze, const cv::Mat& target_mask,
                         double recorded_pupil_mm, FrameReport& r) const;
  // log10 of the mean luminance over the adaptation patch at frame point (x, y).
  double patch_log_mean(const retina::LuminanceField& field, double x, double y, double surround) const;

  Plan plan_;
  std::optional<double> adaptation_;
  std::optional<double> pupil_;  // mm
  std::unique_ptr<RetinaStage> retina_;
  std::unique_ptr<MesopicStage> mesopic_;
  std::unique_ptr<GlareStage> glare_;
  cv::Mat solid_angles_;  // each pixel's solid angle (empty: all equal), for the pupil's field
  double solid_angle_sum_;
};

}  // namespace eyestream::pipeline
