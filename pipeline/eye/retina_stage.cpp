#include "pipeline/eye/retina_stage.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <optional>
#include <opencv2/imgproc.hpp>

#include "io/exr_file.hpp"
#include "io/staged_file.hpp"
#include "retina/afterimage_composite.hpp"

namespace eyestream::pipeline {

namespace {

struct StepGroup {
  double dt = 0.0, x = 0.0, y = 0.0;
  bool closed = false;
  size_t last = 0;  // index of the group's last segment
};

// Merges consecutive segments with one eye state and a gaze within
// `tolerance_px` of the group's first; the group's gaze is the
// time-weighted mean.
std::vector<StepGroup> group_segments(const std::vector<GazeSegment>& segments, double tolerance_px) {
  std::vector<StepGroup> groups;
  double first_x = 0, first_y = 0, wx = 0, wy = 0;
  for (size_t i = 0; i < segments.size(); ++i) {
    const GazeSegment& s = segments[i];
    const bool joins = !groups.empty() && groups.back().closed == s.eye_closed &&
                       std::hypot(s.x - first_x, s.y - first_y) <= tolerance_px;
    if (!joins) {
      groups.push_back({0.0, s.x, s.y, s.eye_closed, i});
      first_x = s.x;
      first_y = s.y;
      wx = wy = 0;
    }
    StepGroup& g = groups.back();
    g.dt += s.duration();
    wx += s.x * s.duration();
    wy += s.y * s.duration();
    if (g.dt > 0) {
      g.x = wx / g.dt;
      g.y = wy / g.dt;
    }
    g.last = i;
  }
  return groups;
}

// The grid sites that bilinear reads at `sites` (CV_32FC2, grid
// coordinates) touch, clipped to the grid, with `sites` made relative to
// that region; none when every read falls outside the grid.
std::optional<cv::Rect> read_region(cv::Mat& sites, cv::Size grid) {
  std::vector<cv::Vec4f> rows(size_t(sites.rows), cv::Vec4f(FLT_MAX, FLT_MAX, -FLT_MAX, -FLT_MAX));
  cv::parallel_for_(cv::Range(0, sites.rows), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y) {
      cv::Vec4f& b = rows[size_t(y)];
      const cv::Vec2f* p = sites.ptr<cv::Vec2f>(y);
      for (int x = 0; x < sites.cols; ++x) {
        b[0] = std::min(b[0], p[x][0]);
        b[1] = std::min(b[1], p[x][1]);
        b[2] = std::max(b[2], p[x][0]);
        b[3] = std::max(b[3], p[x][1]);
      }
    }
  });
  cv::Vec4f box(FLT_MAX, FLT_MAX, -FLT_MAX, -FLT_MAX);
  for (const cv::Vec4f& b : rows)
    box = {std::min(box[0], b[0]), std::min(box[1], b[1]), std::max(box[2], b[2]), std::max(box[3], b[3])};
  if (!(box[0] <= box[2] && box[1] <= box[3])) return cv::Rect(cv::Point(0, 0), grid);  // no ordered position: all
  // Clamped before converting: the positions may be huge or infinite.
  const auto lo = [](float v, int n) { return int(std::floor(std::clamp(v, -1.0f, float(n)))); };
  const auto hi = [](float v, int n) { return int(std::floor(std::clamp(v, -1.0f, float(n)))) + 2; };
  const cv::Rect region =
      cv::Rect(cv::Point(lo(box[0], grid.width), lo(box[1], grid.height)),
               cv::Point(hi(box[2], grid.width), hi(box[3], grid.height))) &
      cv::Rect(cv::Point(0, 0), grid);
  if (region.empty()) return std::nullopt;
  if (region.x != 0 || region.y != 0) sites -= cv::Scalar(region.x, region.y);
  return region;
}

// The grid's half-extent in frame pixels: the retina's reach, rounded up.
cv::Size grid_reach(const FrameProjection& p) {
  const cv::Size2d reach = p.retina_reach();
  return {int(std::ceil(reach.width)), int(std::ceil(reach.height))};
}

}  // namespace

RetinaStage::RetinaStage(const Plan& plan) : RetinaStage(plan, grid_reach(*plan.projection)) {}

RetinaStage::RetinaStage(const Plan& plan, cv::Size reach)
    : plan_(plan),
      grid_(reach.width, reach.height, plan.retina.sites_per_pixel),
      state_(grid_.size(), plan.retina.receptors, plan.retina.double_precision),
      visibility_(grid_.foveal_falloff(plan.retina.fovea_sigma_px)) {
  const cv::Size frame(plan.width, plan.height);
  if (reduced_frame_size(frame) != frame)
    reduction_ = std::make_shared<const retina::AreaReduction>(frame, reduced_frame_size(frame));
}

cv::Mat RetinaStage::dark_stimulus() const {
  // A closed eye after a closed eye sees what it saw: the last stimulus,
  // the same buffer, which unchanged() then knows without comparing.
  if (last_dark_) return last_stimulus_;
  return cv::Mat(grid_.size(), plan_.retina.double_precision ? CV_64FC3 : CV_32FC3,
                 cv::Scalar::all(plan_.dark_cd_m2));
}

void RetinaStage::advance(const cv::Mat& rgb, const std::vector<GazeSegment>& frame_segments,
                          const std::vector<double>& adaptation_log, double surround_cd_m2) {
  // The grid lives on the angle plane (frame_projection.hpp): the scene and
  // the gaze are carried there.
  const FrameProjection& p = *plan_.projection;
  const cv::Scalar surround = cv::Scalar::all(surround_cd_m2);
  // Reduced first, then carried to cone space, so the transform runs on the
  // reduced pixels only. The transform is linear and the area means commute
  // with it; only its clamp of negative cone values (light no real scene
  // has: out-of-gamut or ringing inputs) now acts on the mean instead of on
  // each pixel.
  // Made when a step group needs it: at rest, a still frame's groups are
  // known unchanged by the frame's digest alone.
  cv::Mat lms;
  const auto cone_stimulus = [&]() -> const cv::Mat& {
    if (lms.empty()) {
      const cv::Mat reduced = p.identity() ? grid_.reduce(rgb) : reduce_frame(rgb);
      lms = retina::to_cone_stimulus(reduced, plan_.retina.double_precision ? CV_64F : CV_32F);
    }
    return lms;
  };
  std::vector<GazeSegment> segments = frame_segments;
  for (GazeSegment& s : segments) {
    const cv::Point2d at = p.to_plane({s.x, s.y});
    s.x = at.x;
    s.y = at.y;
  }
  // The frame's digest, at rest only (where a group may be unchanged).
  std::optional<FrameDigest> digest;
  if (plan_.skip && resting_) digest = frame_digest(rgb);
  double frame_dt = 0.0;
  stepped_ = false;
  for (const StepGroup& g : group_segments(segments, plan_.retina.substep_tolerance_px)) {
    // The last stimulus is read again only to know an unchanged one at
    // rest, to catch up time skipped at rest, or as the dark a blink goes
    // on seeing: else it is let go of before the next is made (a grid
    // image, 25 MB at 1080p in `balanced`, not held beside it).
    if (!(plan_.skip && resting_) && !(pending_dt_ > 0) && !(g.closed && last_dark_)) {
      last_stimulus_.release();
      last_dark_ = false;
      unchanged_source_.reset();
    }
    const double curve_log = adaptation_log[g.last];
    std::optional<StimulusSource> source;
    if (digest && !g.closed) source = StimulusSource{*digest, surround_cd_m2, g.x, g.y};
    if (started_ && plan_.skip && resting_ && source && source == unchanged_source_ && same_curve(curve_log)) {
      pending_dt_ += g.dt;  // what unchanged() said of this source last time, it says again
      continue;
    }
    const cv::Mat stimulus = g.closed ? dark_stimulus() : sample(cone_stimulus(), g.x, g.y, surround);
    const retina::ToneCurve curve(curve_log, plan_.tone);
    if (!started_) {
      state_.rest(stimulus, curve);
      started_ = true;
    } else if (plan_.skip && resting_ && unchanged(stimulus, curve_log)) {
      pending_dt_ += g.dt;
      if (source) unchanged_source_ = source;
      continue;
    }
    catch_up();
    last_stimulus_.release();  // (replaced below)
    unchanged_source_.reset();
    state_.step(stimulus, curve, g.dt);
    frame_dt += g.dt;  // time deferred at rest is softened by catch_up()
    last_stimulus_ = stimulus;
    last_dark_ = g.closed;
    last_curve_log_ = curve_log;
    resting_ = false;
    stepped_ = true;
  }
  if (!stepped_) return;
  // Soft afterimages: the departure from equilibrium spreads as sigma^2 =
  // rate * dt, so the look does not depend on the frame rate.
  state_.soften(spread_variance_sites2(frame_dt));
}

cv::Size RetinaStage::reduced_frame_size(cv::Size frame) const {
  const double k = grid_.sites_per_pixel();
  if (k >= 1.0) return frame;
  return {std::max(1, int(std::lround(frame.width * k))), std::max(1, int(std::lround(frame.height * k)))};
}

cv::Mat RetinaStage::reduce_frame(const cv::Mat& frame) const {
  if (!reduction_) return frame;  // the grid as fine as the frame
  cv::Mat out;
  reduction_->apply(frame, out);
  return out;
}

cv::Mat RetinaStage::sample(const cv::Mat& reduced, double plane_x, double plane_y, const cv::Scalar& surround) const {
  const FrameProjection& p = *plan_.projection;
  if (p.identity()) return grid_.sample_reduced(reduced, plane_x, plane_y, surround);
  // Each (reduced) frame pixel lands on the site that sees its direction
  // with the eye turned to the gaze, its light area-averaged there.
  const cv::Point2d gaze = p.to_frame({plane_x, plane_y});
  const cv::Mat sites = p.gaze_positions(gaze, reduced.size(), grid_.sites_per_pixel(), grid_.fovea());
  return FrameProjection::splat(reduced, sites, grid_.size(), surround);
}

double RetinaStage::spread_variance_sites2(double dt_s) const {
  const double sites_per_deg = plan_.pixels_per_degree * grid_.sites_per_pixel();
  return plan_.retina.spread_deg2_per_s * dt_s * sites_per_deg * sites_per_deg;
}

void RetinaStage::catch_up() {
  if (!(pending_dt_ > 0)) return;
  state_.step(last_stimulus_, retina::ToneCurve(last_curve_log_, plan_.tone), pending_dt_);
  state_.soften(spread_variance_sites2(pending_dt_));
  pending_dt_ = 0.0;
}

bool RetinaStage::unchanged(const cv::Mat& stimulus, double curve_log) const {
  if (last_stimulus_.empty() || !same_curve(curve_log)) return false;
  if (stimulus.data == last_stimulus_.data) return true;
  // |s - s_last| <= tol (s_last + dark) at every site and cone.
  cv::Mat excess;
  cv::absdiff(stimulus, last_stimulus_, excess);
  cv::scaleAdd(last_stimulus_, -kStimulusTolerance, excess, excess);
  double worst = 0.0;
  cv::minMaxLoc(excess.reshape(1), nullptr, &worst);
  return worst <= kStimulusTolerance * plan_.dark_cd_m2;
}

void RetinaStage::prepare_afterimages(double gaze_x, double gaze_y) {
  gain_.release();
  bleach_.release();
  drawn_at_.reset();
  draw_ = false;
  if (!(plan_.skip && resting_)) {
    if (!state_.holds_rest()) {
      CV_Assert(!last_stimulus_.empty());
      state_.recall_rest(last_stimulus_, retina::ToneCurve(last_curve_log_, plan_.tone));
    }
    draw_ = afterimage_maps(gaze_x, gaze_y);
  }
  state_.release_rest();
}

bool RetinaStage::composite(const cv::Mat& tone_mapped, cv::Mat& out) {
  if (!draw_) {
    out = tone_mapped;
    return false;
  }
  if (drawn_at_) {  // the whole grid's maps: drawn now, at the gaze
    const cv::Scalar none = cv::Scalar::all(0.0);
    gain_ = grid_.draw(gain_, drawn_at_->x, drawn_at_->y, none);
    bleach_ = grid_.draw(bleach_, drawn_at_->x, drawn_at_->y, none);
  }
  retina::composite_afterimages(tone_mapped, gain_, bleach_, out);
  gain_.release();
  bleach_.release();
  drawn_at_.reset();
  draw_ = false;
  return true;
}

bool RetinaStage::afterimage_maps(double gaze_x, double gaze_y) {
  retina::AfterimageMaps maps;
  const FrameProjection& p = *plan_.projection;
  const cv::Scalar none = cv::Scalar::all(0.0);
  if (p.identity()) {
    // Kept on the grid (the size of the B_inf and R let go of) and drawn
    // in composite(): drawn, they are frame-sized, larger when the grid is
    // coarser than the frame.
    maps = state_.afterimages(plan_.retina.afterimages, visibility_);
    gain_ = maps.gain_excess;
    bleach_ = maps.bleach;
    drawn_at_ = cv::Point2d(gaze_x, gaze_y);
  } else {
    // Drawn at the grid's own resolution (the frame reduced as for the
    // stimulus), where the maps hold all their detail, and enlarged
    // bilinearly in the composite.
    const cv::Size size = reduced_frame_size(p.frame_size());
    cv::Mat sites = p.gaze_positions({gaze_x, gaze_y}, size, grid_.sites_per_pixel(), grid_.fovea());
    // Only the sites the frame reads are made (about a quarter of the grid).
    const std::optional<cv::Rect> region = read_region(sites, grid_.size());
    if (!region) {  // the frame sees no site
      resting_ = whole_grid_rests();
      return false;
    }
    maps = state_.afterimages(plan_.retina.afterimages, visibility_, *region);
    gain_ = grid_.draw_at(maps.gain_excess, sites, none);
    bleach_ = grid_.draw_at(maps.bleach, sites, none);
    // At rest only if the whole grid is: an afterimage out of view now may
    // come into view without the stimulus changing. Checked over the whole
    // grid only when the part in view is at rest.
    if (maps.largest <= kRestTolerance && *region != cv::Rect(cv::Point(0, 0), grid_.size())) {
      resting_ = whole_grid_rests();
      return true;
    }
  }
  resting_ = maps.largest <= kRestTolerance;
  return true;
}

bool RetinaStage::whole_grid_rests() const {
  return state_.largest_afterimage(plan_.retina.afterimages, visibility_) <= kRestTolerance;
}

std::vector<cv::Mat> RetinaStage::save(bool& started) const {
  started = started_;
  std::vector<cv::Mat> mats = state_.save();
  if (mats[2].empty() && !last_stimulus_.empty()) {  // let go of after the last afterimages: the same again
    const retina::RestOfStimulus rest =
        state_.rest_for(last_stimulus_, retina::ToneCurve(last_curve_log_, plan_.tone));
    mats[2] = rest.bleached;
    mats[3] = rest.response;
  }
  mats.push_back(last_stimulus_);
  mats.push_back((cv::Mat_<double>(1, 3) << last_curve_log_, pending_dt_, resting_ ? 1.0 : 0.0));
  return mats;
}

std::string RetinaStage::memory_error(const std::vector<cv::Mat>& mats) const {
  if (mats.size() != 6) return std::to_string(mats.size()) + " state matrices, not 6";
  const cv::Size grid = state_.bleached().size();
  const int type = state_.bleached().type();
  const char* names[5] = {"bleaching", "calcium deficit", "bleaching equilibrium", "response", "last stimulus"};
  const double highest[5] = {1.0, state_.calcium_max(), 1.0, 1.0, 1e30};
  for (int i = 0; i < 5; ++i) {
    const cv::Mat& m = mats[size_t(i)];
    if (m.empty() && i >= 2) continue;
    if (m.size() != grid || m.type() != type)
      return std::string("the ") + names[i] + " matrix is " + std::to_string(m.cols) + "x" + std::to_string(m.rows) +
             " of type " + std::to_string(m.type()) + ", the plan's grid " + std::to_string(grid.width) + "x" +
             std::to_string(grid.height) + " of type " + std::to_string(type);
    if (!cv::checkRange(m, true, nullptr, 0.0, highest[i] * (1 + 1e-6) + 1e-12))
      return std::string("the ") + names[i] + " matrix holds values out of range";
  }
  const cv::Mat& book = mats[5];
  if (book.total() != 3 || book.type() != CV_64F || !cv::checkRange(book)) return "the resting bookkeeping is malformed";
  const double pending_s = book.at<double>(1), resting = book.at<double>(2);
  if (!(pending_s >= 0.0 && pending_s <= 1e9) || (resting != 0.0 && resting != 1.0))
    return "the resting bookkeeping is out of range";
  return "";
}

void RetinaStage::restore(const std::vector<cv::Mat>& mats, bool started) {
  CV_Assert(mats.size() == 6 && mats[5].total() == 3 && mats[5].type() == CV_64F);
  state_.restore({mats.begin(), mats.begin() + 4});
  last_stimulus_ = mats[4].clone();
  unchanged_source_.reset();
  last_dark_ = false;
  last_curve_log_ = mats[5].at<double>(0);
  pending_dt_ = mats[5].at<double>(1);
  resting_ = mats[5].at<double>(2) != 0.0;
  started_ = started;
}

io::StagedFile RetinaStage::stage_state(const std::string& path) const {
  std::vector<cv::Mat> b, c;
  cv::Mat b32, c32;
  state_.bleached().convertTo(b32, CV_32FC3);
  state_.calcium().convertTo(c32, CV_32FC3);
  cv::split(b32, b);
  cv::split(c32, c);
  io::StagedFile file(path);
  io::write_exr_channels(file.temp_path().string(),
                         {{"B.L", b[0]}, {"B.M", b[1]}, {"B.S", b[2]}, {"C.L", c[0]}, {"C.M", c[1]}, {"C.S", c[2]}});
  return file;
}

}  // namespace eyestream::pipeline
