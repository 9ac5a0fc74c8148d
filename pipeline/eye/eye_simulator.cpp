#include "pipeline/eye/eye_simulator.hpp"

#include "pipeline/memory/frame_buffer_pool.hpp"

#include <cmath>
#include <optional>

#include "glare/pupil.hpp"
#include "glare/pupil_dynamics.hpp"
#include "glare/veiling_luminance.hpp"
#include "pipeline/eye/pixel_checks.hpp"
#include "retina/adaptation.hpp"
#include "retina/luminance_field.hpp"
#include "retina/luminance.hpp"
#include "retina/tone_curve.hpp"
#include "retina/tone_map.hpp"

namespace eyestream::pipeline {

EyeSimulator::EyeSimulator(Plan plan)
    : plan_(std::move(plan)),
      retina_(std::make_unique<RetinaStage>(plan_)),
      mesopic_(std::make_unique<MesopicStage>(plan_)),
      glare_(plan_.glare.enabled ? std::make_unique<GlareStage>(plan_) : nullptr),
      solid_angles_(plan_.projection->identity() ? cv::Mat() : plan_.projection->solid_angle_weights()),
      solid_angle_sum_(retina::sum_of_weights(solid_angles_)) {}

double EyeSimulator::patch_log_mean(const retina::LuminanceField& field, double x, double y, double surround) const {
  // The patch is patch_deg wide in true angle at the gaze.
  // (Bounded: a gaze far off a rectilinear frame has an enormous scale.)
  const cv::Vec2d ppd = plan_.projection->local_pixels_per_degree({x, y});
  const double most = 4.0 * (plan_.width + plan_.height);
  return field.patch_log_mean(x, y, std::min(0.5 * plan_.patch_deg * ppd[0], most),
                              std::min(0.5 * plan_.patch_deg * ppd[1], most), surround);
}

io::DisplayFrame EyeSimulator::process(io::SceneFrame frame, const std::vector<GazeSegment>& segments,
                                       FrameReport* report, const cv::Mat& target_mask) {
  // Non-finite pixels are counted and seen as black; they reach no stage.
  const std::int64_t nonfinite = frame.nonfinite >= 0 ? frame.nonfinite : count_nonfinite(frame.rgb);
  cv::Mat scene = nonfinite ? finite_copy(frame.rgb) : frame.rgb;
  // What the lens lets through, for an aged lens (before every stage: the
  // pupil, the adaptation and the glare all see the light that reaches
  // the retina).
  if (plan_.lens_filter) {
    cv::Mat through;
    cv::transform(scene, through, cv::Matx33f(*plan_.lens_filter));
    scene = cv::max(through, 0.0f);
  }
  // What the frame says of the world: beyond its edge (the surround), and
  // the field the pupil responds to.
  auto clock = std::chrono::steady_clock::now();
  StageActivity active;
  StageTimes times;
  // The scene's own field is read on the first frame and where the retina
  // sees the scene itself (no glare ran); else only its mean is, which is
  // made in one pass without the field.
  std::optional<retina::LuminanceField> scene_field_made;
  const auto scene_field = [&]() -> const retina::LuminanceField& {
    if (!scene_field_made) scene_field_made.emplace(scene, plan_.dark_cd_m2, solid_angles_);
    return *scene_field_made;
  };
  if (!glare_ || !adaptation_) scene_field();
  // The frame's mean and its edge's mean (the surround) in one pass over
  // it, with the glare stage's digest of it when that stage asks for one.
  const double edge_band_px = plan_.surround_from_edge ? plan_.pixels_per_degree : 0.0;
  retina::SceneMeans means;
  std::optional<FrameDigest> scene_digest;
  if (scene_field_made) {
    means.mean = scene_field_made->frame_mean();
    if (plan_.surround_from_edge) means.edge = retina::edge_log_mean(scene, edge_band_px, plan_.dark_cd_m2);
  } else if (glare_ && glare_->wants_digest()) {
    // The glare stage's digest of the frame, made in the same pass.
    RowDigests rows(scene);
    means = retina::scene_means(scene, plan_.dark_cd_m2, solid_angles_, solid_angle_sum_, edge_band_px,
                                [&](int y) { rows.add_row(y); });
    scene_digest = rows.digest();
  } else {
    means = retina::scene_means(scene, plan_.dark_cd_m2, solid_angles_, solid_angle_sum_, edge_band_px);
  }
  const double scene_mean = means.mean;
  const double surround = plan_.surround_from_edge ? means.edge : plan_.surround_cd_m2;
  const double field_log = std::log10(std::max(scene_mean, plan_.dark_cd_m2));
  const auto pupil_target = [&](bool closed) {
    return glare::pupil_mm(plan_.glare.viewer, closed ? plan_.dark_log : field_log, plan_.frame_area_deg2());
  };
  // A sequence (or a chunk) starts adapted to its scene, even mid-blink:
  // the viewer was looking at it before. Optics first: the retina sees the
  // glare (docs/model.md), through the adaptation and the pupil at the start of
  // the interval (on the first frame, the scene's target).
  const GazeSegment& first = segments.front();
  const double optics_log =
      adaptation_ ? *adaptation_ : patch_log_mean(scene_field(), first.x, first.y, surround);
  if (!pupil_) pupil_ = pupil_target(false);
  // The optics' pupil: the recorded one when asked for and the log has
  // one for this frame, else the model's (which goes on either way).
  const double recorded = plan_.pupil_from_gaze ? first.recorded_pupil_mm : NAN;
  const double optics_pupil = std::isfinite(recorded) ? recorded : *pupil_;
  if (glare_) {
    glare_->set_moment(frame.time_s, first.x, first.y);
  }
  cv::Mat retinal =
      glare_ ? glare_->apply(scene, optics_log, surround, optics_pupil, &active.glare, &active.glare_reused,
                             scene_digest ? &*scene_digest : nullptr)
             : scene;
  times.glare_ms = lap_ms(clock);
  // The later stages read the retinal image; only the report reads the
  // scene again. Let go of it (25 MB at 1080p) while they run.
  if (retinal.data != scene.data && !plan_.report) {
    scene.release();
    frame.rgb.release();
  }

  // Global adaptation: one exact step per gaze segment (Jacobs et al. 2015
  // eq. 3) toward the log of the mean retinal luminance around the gaze;
  // the pupil follows the field with its own time constants.
  const retina::LuminanceField field =
      retinal.data == scene.data ? scene_field() : retina::LuminanceField(retinal, plan_.dark_cd_m2);
  double target = plan_.dark_log;
  std::vector<double> adapted;
  adapted.reserve(segments.size());
  for (const GazeSegment& seg : segments) {
    const double scene_log = patch_log_mean(field, seg.x, seg.y, surround);
    target = seg.eye_closed ? plan_.dark_log : scene_log;
    if (!adaptation_) adaptation_ = scene_log;
    adaptation_ = retina::adaptation_step(*adaptation_, target, seg.duration(), plan_.adaptation);
    adapted.push_back(*adaptation_);
    pupil_ = glare::pupil_step(*pupil_, pupil_target(seg.eye_closed), seg.duration(), plan_.pupil);
  }
  const GazeSegment& last = segments.back();
  times.adaptation_ms = lap_ms(clock);
  // Photoreceptor state on the retinal grid.
  retina_->advance(retinal, segments, adapted, surround);
  active.retina = retina_->stepped();
  times.retina_ms = lap_ms(clock);
  retina_->prepare_afterimages(last.x, last.y);  // (the afterimages' time)
  const double drawing_ms = lap_ms(clock);

  io::DisplayFrame out;
  out.index = frame.index;
  out.time_s = frame.time_s;
  const retina::ToneCurve curve(*adaptation_, plan_.tone);
  cv::Mat seen;
  if (last.eye_closed) {
    seen = cv::Mat::zeros(retinal.size(), CV_32FC3);
    retinal.release();  // (as render() does once it has tone-mapped it)
  } else
    mesopic_->render(std::move(retinal), curve, *adaptation_, frame.time_s, seen, &active, last.x, last.y, field.luminance());
  times.mesopic_ms = lap_ms(clock);
  active.afterimages = retina_->composite(seen, out.linear);
  times.afterimage_ms = drawing_ms + lap_ms(clock);
  if (report) {
    report->adaptation_log = *adaptation_;
    report->target_log = target;
    report->gaze_x = last.x;
    report->gaze_y = last.y;
    report->eye_closed = last.eye_closed;
    report->nonfinite_pixels = nonfinite;
    report->active = active;
    report->times = times;
    if (plan_.report) fill_glare_report(scene, last, target_mask, recorded, *report);
  }
  trim_frame_buffers();  // what the pool holds follows the frames' sizes
  return out;
}

void EyeSimulator::fill_glare_report(const cv::Mat& scene, const GazeSegment& gaze, const cv::Mat& target_mask,
                                     double recorded_pupil_mm, FrameReport& r) const {
  cv::Mat luminance(scene.size(), CV_32F);
  scene.forEach<cv::Vec3f>(
      [&](const cv::Vec3f& p, const int* pos) { luminance.at<float>(pos[0], pos[1]) = retina::photopic_luminance(p); });
  double peak;
  cv::minMaxLoc(luminance, nullptr, &peak);
  r.peak_cd_m2 = peak;
  // The pupil the optics take (the recorded one when there is one), and
  // the model's beside it.
  const double pupil = std::isfinite(recorded_pupil_mm) ? recorded_pupil_mm : *pupil_;
  r.pupil_mm = pupil;
  r.pupil_model_mm = *pupil_;
  r.pupil_recorded_mm = std::isfinite(recorded_pupil_mm) ? recorded_pupil_mm : -1.0;
  const std::optional<TargetLuminance> target = measure_target(luminance, target_mask);
  if (target) {
    r.target_cd_m2 = target->target_cd_m2;
    r.background_cd_m2 = target->background_cd_m2;
  }
  if (!glare_ || gaze.eye_closed) return;
  const std::optional<double> veil = glare_->veil_at(luminance, *adaptation_, pupil, gaze.x, gaze.y, plan_.veil_exclusion_deg);
  if (veil) {
    r.veil_cd_m2 = *veil;
    r.ti_percent = glare::threshold_increment(*veil, std::pow(10.0, *adaptation_));
  }
  if (target) {
    const std::optional<double> target_veil =
        glare_->veil_at(luminance, *adaptation_, pupil, target->x, target->y, plan_.veil_exclusion_deg);
    if (target_veil) r.target_veil_cd_m2 = *target_veil;
  }
}

EyeMemory EyeSimulator::save() const {
  EyeMemory m;
  m.adaptation_log = adaptation_;
  m.pupil_mm = pupil_;
  m.retina = retina_->save(m.retina_started);
  return m;
}

std::string EyeSimulator::memory_error(const EyeMemory& m) const {
  const auto finite = [](const std::optional<double>& v) { return !v || std::isfinite(*v); };
  if (!finite(m.adaptation_log) || !finite(m.pupil_mm) || (m.pupil_mm && !(*m.pupil_mm > 0.0 && *m.pupil_mm < 20.0)))
    return "adaptation or pupil out of range";
  return retina_->memory_error(m.retina);
}

void EyeSimulator::restore(const EyeMemory& m) {
  adaptation_ = m.adaptation_log;
  pupil_ = m.pupil_mm;
  retina_->restore(m.retina, m.retina_started);
}

}  // namespace eyestream::pipeline
