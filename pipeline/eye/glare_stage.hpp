// The eye's optics: turns the scene into the retinal image the retina sees
// (Spencer et al. 1995, Yoshida et al. 2008). Bright veils then also adapt and bleach.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <optional>

#include "glare/fft_convolver.hpp"
#include "retina/bilinear_axis.hpp"
#include "glare/split_convolver.hpp"
#include "glare/wave_lines.hpp"
#include "glare/psf_kernel.hpp"
#include "pipeline/memory/frame_digest.hpp"
#include "pipeline/settings/plan.hpp"

namespace eyestream::pipeline {

class GlareStage {
 public:
  // Builds the component kernels and their spectra once for the sequence.
  explicit GlareStage(const Plan& plan);

  // The retinal image of `rgb` (finite, cd/m^2) for a viewer adapted to
  // 10^adaptation_log with the pupil `pupil_mm` (0: the pupil of that
  // adaptation level). Mode "full" (the default) is the eye: the whole image
  // goes through the PSF, and the surround (surround_cd_m2, everything
  // beyond the frame) scatters in, so a uniform field stays uniform up to
  // the frame's edge. Unless the plan says not to skip, a uniform field
  // (uniform_field.hpp, within kUniformTolerance) is returned as it is, and
  // a frame equal to the last one, with the same optics (adaptation and
  // pupil quantised to 1e-4 log10 units and 1e-3 mm), returns the last
  // result once the frame has come twice in a row (Cache, below); *ran is
  // false then (and *reused true for the reuse).
  cv::Mat apply(const cv::Mat& rgb, double adaptation_log, double surround_cd_m2, double pupil_mm = 0.0,
                bool* ran = nullptr, bool* reused = nullptr, const FrameDigest* digest = nullptr);

  // Whether apply() reads the frame's digest (full mode, skipping on).
  // A caller that made it in a pass over the frame of its own passes it as
  // `digest`; else apply() makes it.
  bool wants_digest() const { return plan_.skip && plan_.glare.full; }

  // The frame's moment for the wave-optics lines (--flare-model wave): its
  // time and the gaze (frame pixels). Set before apply().
  void set_moment(double time_s, double gaze_x, double gaze_y) { moment_ = {time_s, {gaze_x, gaze_y}}; }
  // The error bound of skipping a uniform field (relative).
  static constexpr double kUniformTolerance = 1e-3;

  // The veiling luminance (cd/m^2) at (x, y) from the light more than
  // exclusion_deg away (glare/veiling_luminance.hpp), for the viewer at
  // this adaptation and pupil; nothing with the Gaussian model (it is no
  // eye PSF).
  std::optional<double> veil_at(const cv::Mat& luminance, double adaptation_log, double pupil_mm, double x, double y,
                                double exclusion_deg) const;

  // The PSF's component kernels (empty with the Gaussian model, and with
  // the split engine unless a report needs them).
  const glare::ComponentKernels& kernels() const { return kernels_; }

 private:
  // Convolves `rgb` (frame pixels) with the PSF of weights `w` at true
  // angles: on the angle plane (frame_projection.hpp) unless the frame is
  // its own, the light the PSF keeps within its centre pixel staying on the
  // frame's pixels, unresampled.
  // With surround_cd_m2 > 0 (full mode), the surround's scattered light too.
  cv::Mat spread(const cv::Mat& rgb, const glare::PsfWeights& w, double surround_cd_m2 = 0.0) const;
  // Off the frame's own plane: the light the PSF moves out of its pixel,
  // on the glare frame's pixels (the halved frame's, or the frame's).
  // `finish` as FrameProjection::to_frame_image's.
  cv::Mat moved_light(const cv::Mat& rgb, const glare::ChannelWeights& w,
                      const FrameProjection::RowFinish& finish = {}) const;
  // The same from the glare frame's flux on the plane (to_plane_flux's).
  cv::Mat moved_light_of_flux(cv::Mat flux, const glare::ChannelWeights& w,
                              const FrameProjection::RowFinish& finish = {}) const;
  // What in_frame_ holds for a component: spread (the frame's own plane)
  // or moved light of a frame of ones (each channel with its own weights:
  // a component per channel), from in_frame_source() (not changed).
  cv::Mat in_frame_share(const cv::Mat& source, const glare::ChannelWeights& w) const;
  // What in_frame_share() spreads: a frame of ones on the frame's own
  // plane, else the plane's flux of the glare frame's ones.
  cv::Mat in_frame_source() const;
  // The convolution on the angle plane.
  cv::Mat spread_plane(const cv::Mat& plane, const glare::ChannelWeights& w) const;
  // Per channel, the share of a pixel's light the PSF of weights `w` keeps
  // in that pixel.
  cv::Vec3f kept_share(const glare::PsfWeights& w) const;
  // Adds the light the surround scatters into the frame: S (1 - M(x)),
  // M(x) the share of the PSF at x that falls inside the frame, to `light`
  // (spread's result on the frame's own plane, moved_light's otherwise,
  // whose M is the maps' plus the kept share).
  void add_surround(cv::Mat& light, const glare::PsfWeights& w, double surround_cd_m2) const;
  // The same for one row y of `light` at a time (none without a surround).
  FrameProjection::RowFinish surround_rows(const glare::PsfWeights& w, double surround_cd_m2) const;

  // The wave-optics lines of `light` (what the engine spread) added to
  // `retinal`, when the plan asks for them: into a new image when
  // `retinal` is shared (the cache keeps it), else in place.
  cv::Mat with_wave_lines(const cv::Mat& light, const glare::PsfWeights& w, double pupil_mm, cv::Mat retinal,
                          bool shared);

  const Plan plan_;
  const glare::EyeOptics optics_;
  std::unique_ptr<glare::WaveLines> wave_;
  struct {
    double time_s = 0.0;
    cv::Point2d gaze;
  } moment_;
  // The frame halved each way (area mean) before the splat to the plane,
  // or empty: a plane at half the frame's px/deg or less receives about
  // one frame pixel in four per plane pixel, and a 2x2 mean carries the
  // same light as its four pixels (kept light stays full-resolution).
  cv::Size halved_;
  cv::Mat to_glare_frame(const cv::Mat& frame) const;
  // Where each frame pixel reads the halved frame when spread() brings the
  // moved light back (as cv::resize INTER_LINEAR), across and down.
  std::shared_ptr<const retina::BilinearAxis> up_cols_, up_rows_;
  // The angle plane of the convolution (the plan's, or one at
  // plan.glare.plane_scale of its resolution, from the halved frame when
  // there is one) and its px/deg.
  std::shared_ptr<const FrameProjection> plane_;
  double ppd_;
  glare::ComponentKernels kernels_;
  std::unique_ptr<glare::FftConvolver> convolver_;     // exact engine
  std::unique_ptr<glare::SplitConvolver> split_;       // or the split one
  // Full mode: per component (core, inner, outer, halo), the share of the
  // PSF centred at each pixel that falls inside the frame (CV_32FC3, or
  // CV_32F when every channel holds the same); off the frame's own plane,
  // without the kept share and at moved_light's size. With the PSF's
  // kernels the first map holds the core's, inner's and outer's shares,
  // one a channel, as their one pass makes them (`triple_`).
  std::vector<cv::Mat> in_frame_;
  bool triple_ = false;
  // Per component (core, inner, outer, halo) and channel, the kernel's
  // centre pixel.
  cv::Vec3d centre_[4];
  // The last full-mode frame, for still scenes: known by its digest (no
  // copy of it is kept), with the optics it was seen with, and its glare
  // once the frame has come twice in a row (whatever the optics did):
  // moving footage keeps no glare image (25 MB at 1080p) through the
  // frame's later stages, and a still scene runs its glare on its second
  // frame too.
  struct Cache {
    FrameDigest scene;
    cv::Mat retinal;
    glare::PsfWeights weights;
    double surround = 0.0;
    // The last frame, with the same optics (its glare kept or not).
    bool seen(const FrameDigest& rgb, const glare::PsfWeights& w, double surround_cd_m2) const;
    // seen(), with the glare kept.
    bool matches(const FrameDigest& rgb, const glare::PsfWeights& w, double surround_cd_m2) const;
    void keep(const FrameDigest& rgb, const glare::PsfWeights& w, double surround_cd_m2, const cv::Mat& retinal);
  };
  Cache cache_;
};

}  // namespace eyestream::pipeline
