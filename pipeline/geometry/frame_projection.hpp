// How a frame's pixels map to directions in the viewer's visual field, and
// the angle plane in which the optics and the retina work.
//
// A renderer's or a driving simulator's frame is a rectilinear (pinhole)
// projection: a pixel r pixels from the centre looks atan(r / f) away from
// the optical axis, f = (width / 2) / tan(fov / 2). A flat display seen
// from its axis is the same projection of the viewer's field, so
// rectilinear is the default. On a 120 deg frame a pixel at 50 deg covers
// 2.4 times fewer degrees than one at the centre, and a PSF laid on the
// frame's pixels with one px/deg would be wrong by that much.
//
// The angle plane is the azimuthal equidistant projection about the frame's
// centre at the centre's scale: a point's distance from the plane's centre
// is its true angle from the axis, so distances along any line through the
// centre are true angles, and elsewhere they are stretched across that line
// by at most theta / sin(theta) (4.7 % at 30 deg, 14 % at 50 deg). The
// optics (glare/) and the retinal grid (retina/) take one px/deg, the
// plane's; the frame's pixels are carried into the plane (area-averaged,
// each weighted by its solid angle) and back (bilinearly).
//
// An equidistant frame (fisheye renders, angle-mapped stimuli) already is
// its own angle plane: nothing is resampled.
#pragma once

#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pipeline/geometry/fixed_splat.hpp"

namespace eyestream::pipeline {

enum class Projection { rectilinear, equidistant };

Projection projection_from_name(const std::string& name);  // "rectilinear" or "equidistant"
const char* projection_name(Projection p);

class FrameProjection {
 public:
  // A width x height frame whose horizontal field of view is fov_deg; the
  // plane has `scale` times the frame's px/deg at its centre (1: the same;
  // 0.5: a quarter of the pixels, for a cheaper convolution).
  FrameProjection(int width, int height, double fov_deg, Projection kind, double scale = 1.0);

  Projection kind() const { return kind_; }
  // True when the frame is its own angle plane (equidistant, at scale 1):
  // every conversion below is the identity and nothing needs resampling.
  bool identity() const { return kind_ == Projection::equidistant && scale_ == 1.0; }
  cv::Size frame_size() const { return frame_; }
  cv::Size plane_size() const { return plane_; }
  // The plane's pixels per degree: the frame's at its centre times the scale.
  double pixels_per_degree() const { return ppd_; }

  // Points, origin at the top-left corner of the top-left pixel.
  cv::Point2d to_plane(cv::Point2d frame) const;
  cv::Point2d to_frame(cv::Point2d plane) const;
  // The true angle (deg) between the directions of two frame points.
  double angle_deg(cv::Point2d a, cv::Point2d b) const;
  // Frame pixels per degree along x and y at a frame point.
  cv::Vec2d local_pixels_per_degree(cv::Point2d frame) const;
  // The frame's solid angle in square degrees.
  double solid_angle_deg2() const;
  // Each frame pixel's solid angle over the centre pixel's (CV_32F).
  cv::Mat solid_angle_weights() const;

  // Where the centres of an image's pixels (the frame, or the frame
  // resized to `size`) lie in the viewer's field when the gaze is at frame
  // point `gaze`: the azimuthal equidistant projection about the gaze's
  // direction, x along the frame's horizontal there, at the plane's scale,
  // mapped to origin + scale * offset (CV_32FC2). Unlike the plane, this is
  // exact in every direction from the gaze: an eye's rotation. Computed
  // exactly every 4 pixels and bilinearly between (within 0.01 px at
  // 960x540, 120 deg).
  cv::Mat gaze_positions(cv::Point2d gaze, cv::Size size, double scale, cv::Point2d origin) const;
  // One frame point's offset (plane px) from a gaze, as above: x along the
  // frame's horizontal at the gaze, the length the true angle.
  cv::Vec2d gaze_offset(cv::Point2d gaze, cv::Point2d point) const;
  // The largest offsets across and down (plane px) of any frame point from
  // any gaze on the frame: how far the retinal grid must reach (the
  // frame's own size when equidistant).
  cv::Size2d retina_reach() const;

  // A frame image (CV_32FC1, CV_32FC3 or CV_64FC3) carried into the plane,
  // resized to `size` (0: the plane's): each plane pixel the mean of the
  // frame pixels that land on it (bilinear splat, normalised), `outside`
  // where the plane sees beyond the frame. Deterministic whatever the
  // thread count.
  cv::Mat to_plane_mean(const cv::Mat& frame, const cv::Scalar& outside, cv::Size size = {}) const;
  // The same for any positions (CV_32FC2, the image's size; pixel centres
  // of the `size` target at integers): an image carried onto a target.
  static cv::Mat splat(const cv::Mat& image, const cv::Mat& positions, cv::Size size, const cv::Scalar& outside);
  // The same as luminance times solid angle over the plane centre's, so
  // that a shift-invariant convolution on the plane spreads each frame
  // pixel's flux: mean times sin(theta) / theta, 0 beyond the frame.
  cv::Mat to_plane_flux(const cv::Mat& frame) const;
  // to_plane_flux of a frame of ones (CV_32FC3), bit for bit, made from
  // the splat's weights alone (not for the identity).
  cv::Mat flux_of_ones() const;
  // A plane image (plane-sized, CV_32FC3) sampled bilinearly at every
  // frame pixel's direction (the plane itself for the identity).
  cv::Mat to_frame_image(const cv::Mat& plane) const;
  // The same into `out` (not for the identity), handing each frame row to
  // `finish` (row y, its pixels) while it is still in the cache: later
  // per-pixel work in the same sweep. Rows go to `finish` in stripes on
  // any thread.
  using RowFinish = std::function<void(int y, float* row)>;
  void to_frame_image(const cv::Mat& plane, cv::Mat& out, const RowFinish& finish) const;
  // The plane position of every frame pixel's centre (CV_32FC2; not for
  // the identity, which has none).
  const cv::Mat& plane_positions() const;
  // Makes the maps that carry images between the frame and the plane now
  // rather than at their first use (not for the identity): the glare
  // stage's set-up, so that its first frame does not wait for them.
  void make_carriage_now() const { carriage(); }

 private:
  // Rectilinear: the gaze's direction ez and the axes ex (the frame's
  // horizontal there) and ey across it, made once for many points.
  struct GazeAxes {
    cv::Vec3d ex, ey, ez;
  };
  GazeAxes gaze_axes(cv::Point2d gaze) const;
  // Rectilinear: the plane offset over the frame offset (X, Y) from the
  // centre, which depends on |X| and |Y| only.
  double radial_scale(double X, double Y) const;
  cv::Vec2d offset_from(const GazeAxes& axes, cv::Point2d point) const;

  Projection kind_;
  cv::Size frame_, plane_;
  double fov_deg_, scale_;
  double f_px_ = 0.0, fp_ = 0.0;  // rectilinear: the frame's focal length, the plane's (f_px_ scale), in px
  double frame_ppd_, ppd_;        // the frame's px/deg at its centre, and the plane's
  // What carries images between the frame and the plane (the positions,
  // cv::remap's maps, the flux weights and the fixed splat; for
  // to_plane_mean, to_plane_flux, flux_of_ones, to_frame_image and
  // plane_positions):
  // made on the first such call or by make_carriage_now(), once. The
  // points' and the gaze's conversions do not need it, so a projection
  // used only for them (the retina's, when the glare has a plane of its
  // own) never makes it: at 1080p three frame-sized maps and two
  // plane-sized ones, with their temporaries, which a one-frame `fast` run
  // no longer touches (docs/performance.md).
  struct Carriage;
  const Carriage& carriage() const;
  void make_carriage(Carriage& c) const;
  std::shared_ptr<Carriage> carriage_;  // copies of the projection share it
};

}  // namespace eyestream::pipeline
