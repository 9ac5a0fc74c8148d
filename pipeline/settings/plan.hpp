// Settings compiled once per sequence into what every frame runs with
// (the OpenColorIO Config -> Processor idea).
#pragma once

#include <optional>

#include <memory>
#include <string>

#include "glare/eye_optics.hpp"
#include "glare/pupil_dynamics.hpp"
#include "io/frame_source.hpp"
#include "pipeline/geometry/frame_projection.hpp"
#include "pipeline/settings/settings.hpp"
#include "retina/acuity_loss.hpp"
#include "retina/mesopic.hpp"
#include "retina/photoreceptor.hpp"
#include "retina/retina_state.hpp"

namespace eyestream::pipeline {

struct RetinaPlan {
  double sites_per_pixel = 0.25;
  bool double_precision = false;
  double substep_tolerance_px = 0.0;
  double spread_deg2_per_s = 0.0;
  retina::PhotoreceptorParams receptors;
  retina::AfterimageOptions afterimages;
  double fovea_sigma_px = 0.0;  // afterimage visibility fall-off; 0: none
};

struct MesopicPlan {
  bool enabled = true;
  retina::MesopicParams colour;
  bool acuity = true;
  retina::AcuityParams acuity_params;
};

struct GlarePlan {
  bool enabled = true;
  bool gaussian = false;             // Yoshida et al. 2008's cheap kernel instead of the eye's PSF
  glare::PsfModel model = glare::PsfModel::vos;
  bool flare_lines = true;
  bool wave_lines = false;           // the lines by wave optics, frame by frame (flare_lines then off in the kernels)
  int tail_factor = 1;               // Vos PSF: 1 exact FFT engine; >= 2 split engine, tail reduced this much
  double plane_scale = 1.0;          // the convolution's px/deg over the frame's at its centre
  double gaussian_sigma_deg = 0.34;  // Yoshida et al. 2008
  bool full = false;
  double display_peak_cd_m2 = 100.0;
  glare::ViewerProfile viewer;
};

struct Plan {
  int width = 0, height = 0;
  // The lens's yellowing for the viewer's age (glare/lens_density.hpp),
  // applied to the scene before every stage; unset: the standard observer.
  std::optional<cv::Matx33f> lens_filter;
  // The optics take the pupil the gaze log recorded, where it has one.
  bool pupil_from_gaze = false;
  double frames_per_second = 30.0;
  double fov_deg = 0.0;
  // The frame's directions and the angle plane the optics and the retina
  // work in; pixels_per_degree is the plane's (the frame's at its centre).
  std::shared_ptr<const FrameProjection> projection;
  double pixels_per_degree = 0.0;
  double patch_deg = 1.5;  // side of the adaptation patch
  double surround_cd_m2 = 1.0;                       // fixed surround
  bool surround_from_edge = true;                    // or the frame's edge, frame by frame (settings.hpp)
  glare::PupilDynamics pupil;
  double dark_cd_m2 = 1e-6, dark_log = -6.0;
  retina::AdaptationParams adaptation;
  retina::ToneCurveParams tone;
  retina::EncodingParams encoding;
  GlarePlan glare;
  RetinaPlan retina;
  MesopicPlan mesopic;
  // Scene-adaptive activation: skip glare on frames with nothing above the
  // display peak, the retina and its afterimages while at rest, acuity loss
  // where no band can be lost (stage_activity.hpp). false: run every stage.
  bool skip = true;
  bool report = false;  // fill the disability-glare fields of FrameReport
  double veil_exclusion_deg = 1.0;

  // One "name = value" line per resolved setting.
  std::string describe() const;

  // The frame's solid angle (deg^2): the pupil's adapting field when the
  // viewer names none.
  double frame_area_deg2() const { return projection->solid_angle_deg2(); }
  // The angle plane's size (the frame's when equidistant).
  cv::Size plane_size() const { return projection->plane_size(); }

  // The viewer's optics for this frame (glare/eye_optics.hpp).
  glare::EyeOptics eye_optics() const {
    return glare::EyeOptics(glare.viewer, glare.model, glare.flare_lines, frame_area_deg2(), pixels_per_degree);
  }
};

// UsageError when the settings contradict each other (plateau-low must be
// below plateau-high).
Plan compile_plan(const Settings& s, const io::SourceInfo& source);

}  // namespace eyestream::pipeline
