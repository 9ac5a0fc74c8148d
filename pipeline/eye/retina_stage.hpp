// The retina stage of the eye simulator: per-cone bleaching and calcium
// state on a retina-fixed grid, stepped through each frame's gaze segments,
// and the afterimages it adds to the display (Jacobs et al. 2015 sec. 2.2).
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/staged_file.hpp"
#include "pipeline/eye/gaze_timeline.hpp"
#include "pipeline/memory/frame_digest.hpp"
#include "pipeline/settings/plan.hpp"
#include "retina/area_reduction.hpp"
#include "retina/retina_state.hpp"
#include "retina/retinal_grid.hpp"

namespace eyestream::pipeline {

// Largest afterimage term (relative gain excess, or bleaching signal in
// display-linear units) that counts as "at rest": below it, drawing the
// afterimages changes a display value by under 5e-5 of full scale, far
// below one 8-bit code value even where sRGB is steepest.
inline constexpr double kRestTolerance = 5e-5;
// Largest relative change of a site's stimulus that counts as unchanged.
inline constexpr double kStimulusTolerance = 1e-4;

class RetinaStage {
 public:
  explicit RetinaStage(const Plan& plan);

  // Steps the state through `segments` (one frame interval) with the scene
  // `rgb` (cd/m^2); `adaptation_log[i]` is the global adaptation after
  // segment i. Consecutive segments with the same eye state and a gaze
  // within the plan's sub-step tolerance are stepped together. The first
  // call starts the retina at rest for its first stimulus. Sites looking
  // beyond the frame see surround_cd_m2.
  void advance(const cv::Mat& rgb, const std::vector<GazeSegment>& segments, const std::vector<double>& adaptation_log,
               double surround_cd_m2);

  // Makes the afterimage maps at the gaze (x, y) for composite() (drawn to
  // the frame, or on the frame's own plane kept on the grid until then),
  // right after advance(): then the state lets go of its equilibrium B_inf and
  // response R (two grid images, about 19 MB at 1080p in `balanced`), which
  // only the afterimages and the next step read, so they are not held
  // through the frame's tone mapping and acuity loss; the next step makes
  // them again, and a checkpoint recomputes them from the last stimulus.
  void prepare_afterimages(double gaze_x, double gaze_y);
  // Adds the prepared afterimages to the tone-mapped frame. Returns false
  // when it drew nothing because the retina is at rest.
  bool composite(const cv::Mat& tone_mapped, cv::Mat& out);

  // Whether the last advance() stepped the state (false: skipped at rest).
  bool stepped() const { return stepped_; }

  // Writes B and C per cone (channels B.L, B.M, B.S, C.L, C.M, C.S) of the
  // grid as a float EXR, left under its temporary name for the caller to
  // commit.
  io::StagedFile stage_state(const std::string& path) const;

  const retina::RetinaState& state() const { return state_; }
  // Checkpoints: the state's matrices, the resting bookkeeping, and
  // whether it has started.
  std::vector<cv::Mat> save(bool& started) const;
  void restore(const std::vector<cv::Mat>& mats, bool started);
  // What is wrong with `mats` for this plan's grid (empty: nothing): their
  // count, each one's type and size, finite values within the state's range.
  std::string memory_error(const std::vector<cv::Mat>& mats) const;
  const retina::RetinalGrid& grid() const { return grid_; }

 private:
  // With the grid's half-extent in frame pixels (the retina's reach, rounded up).
  RetinaStage(const Plan& plan, cv::Size reach);
  // Whether no site of the grid departs from rest by more than
  // kRestTolerance (the afterimage maps of the whole grid).
  bool whole_grid_rests() const;
  // The drawn maps into gain_ and bleach_; whether composite() draws them.
  bool afterimage_maps(double gaze_x, double gaze_y);
  cv::Mat gain_, bleach_;  // drawn afterimage maps, between prepare_afterimages() and composite()
  std::optional<cv::Point2d> drawn_at_;  // or the grid's maps, to draw at this gaze (frame's own plane)
  bool draw_ = false;
  // The frame averaged down to about the grid's resolution (sites per
  // pixel below 1), where the cone stimulus is sampled and the
  // afterimages are drawn.
  cv::Size reduced_frame_size(cv::Size frame) const;
  cv::Mat reduce_frame(const cv::Mat& frame) const;
  std::shared_ptr<const retina::AreaReduction> reduction_;  // the plan's frame to reduced_frame_size(), if smaller
  // The grid's stimulus for the gaze at plane point (plane_x, plane_y).
  cv::Mat sample(const cv::Mat& reduced, double plane_x, double plane_y, const cv::Scalar& surround) const;

  const Plan plan_;
  retina::RetinalGrid grid_;
  retina::RetinaState state_;
  cv::Mat visibility_;  // foveal fall-off of afterimages on the grid
  // The grid's stimulus with the eye closed (uniform dark), made when a
  // blink needs it: kept for the whole run it held a grid image (about 10 MB at
  // 1080p in `balanced`) through every open-eyed frame.
  cv::Mat dark_stimulus() const;
  bool started_ = false;
  // Scene-adaptive activation (plan.skip): a retina at rest
  // (every afterimage term below kRestTolerance) that keeps receiving the
  // stimulus it was last stepped with, under the same tone curve, is not
  // stepped; the time skipped is stepped in one exact step when the
  // stimulus changes (the step is exact for a constant stimulus, Jacobs et al. 2015
  // eqs. 5 and 9, so one long step equals many short ones).
  void catch_up();
  // The afterimage spread over dt_s seconds, in grid sites^2.
  double spread_variance_sites2(double dt_s) const;
  bool unchanged(const cv::Mat& stimulus, double curve_log) const;
  bool same_curve(double curve_log) const { return std::abs(curve_log - last_curve_log_) <= 1e-9; }
  // What a stimulus is made from: the retinal image (by its digest), the
  // surround and the gaze on the plane. Equal sources give the same
  // stimulus, bit for bit.
  struct StimulusSource {
    FrameDigest image;
    double surround = 0.0, x = 0.0, y = 0.0;
    bool operator==(const StimulusSource& o) const {
      return image == o.image && surround == o.surround && x == o.x && y == o.y;
    }
  };
  // At rest, the source of the last stimulus found unchanged against
  // last_stimulus_: the same source again is unchanged again, known without
  // carrying the frame to the grid (a still scene's frames at rest). Let go
  // of whenever last_stimulus_ changes.
  std::optional<StimulusSource> unchanged_source_;
  cv::Mat last_stimulus_;
  bool last_dark_ = false;  // last_stimulus_ is dark_stimulus()'s
  double last_curve_log_ = 0.0;
  double pending_dt_ = 0.0;  // seconds skipped at rest, not yet stepped
  bool resting_ = false;     // the last drawn afterimages were all below kRestTolerance
  bool stepped_ = false;
};

}  // namespace eyestream::pipeline
