// Everything a run is configured with: module parameter structs (each with
// its defaults next to its model) plus the run's own options. Declared for
// the command line and config file in run_parameters.cpp.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "glare/pupil_dynamics.hpp"
#include "glare/viewer.hpp"
#include "io/exr_sequence_source.hpp"
#include "io/video_source.hpp"
#include "io/sink_factory.hpp"
#include "pipeline/geometry/viewing_geometry.hpp"
#include "retina/acuity_loss.hpp"
#include "retina/adaptation.hpp"
#include "retina/display_encoding.hpp"
#include "retina/mesopic.hpp"
#include "retina/photoreceptor.hpp"
#include "retina/tone_curve.hpp"

namespace eyestream::pipeline {

struct Settings {
  // Files.
  std::string input, gaze, output, config;
  std::string gaze_units = "px";
  std::string bad_pixels = "clamp";  // NaN or infinite pixels: clamp (show black, count) or fail
  std::string gaze_format = "auto";  // auto, native, pupil-core, neon, neon-surface, tobii, eyelink
  double gaze_offset_s = 0.0;
  std::optional<double> gaze_sync_s;
  std::string gaze_sync_message;  // EyeLink: the first MSG holding this text is frame 0
  std::string gaze_blinks = "auto";  // Pupil Core, Neon: auto (beside the export), none, or a path
  std::string gaze_pupils = "auto";  // Pupil Core, Neon pupil files: auto (beside the export), none, or a path
  std::string gaze_recording;     // Neon, Tobii: the recording to read of several
  std::string gaze_eye = "average";  // EyeLink binocular: left, right or average
  double gaze_confidence = 0.6;
  int gaze_source_width = 0, gaze_source_height = 0;

  io::ExrSequenceOptions exr;
  io::VideoSourceOptions video_input;
  std::string frame_size;  // WxH of raw frames on standard input (-i -)
  io::SinkOptions sink;
  ViewingGeometry geometry;

  // Retina.
  retina::AdaptationParams adaptation;
  retina::ToneCurveParams tone;
  double adaptation_patch_deg = 1.5;  // side of the square patch around the gaze (docs/model.md: 1-2 deg)
  // What lies beyond the frame (seen by retina sites looking outside it,
  // counted in the adaptation patch, scattered in by the glare): unset, the
  // world continues at the geometric mean luminance of the frame's outer
  // 1 deg band, frame by frame; set, that many cd/m^2 (a display in a room).
  std::optional<double> surround_cd_m2;
  double dark_cd_m2 = 1e-6;           // what closed eyes see; floor of all log luminances

  // Optics.
  glare::ViewerProfile viewer;
  bool glare = true;
  // vos: Spencer et al. 1995's PSF; cie: CIE 146 scatter; gaussian: Yoshida et al. 2008's kernel
  std::string psf_model = "vos";
  glare::PupilDynamics pupil_dynamics;
  std::string pupil_model = "moon-spencer";  // or watson-yellott (glare/pupil.hpp)
  bool flare_lines = true;            // radial streaks of corona and halo (glare/flare_lines.hpp)
  std::optional<double> eyelid_mrd1_mm;  // the viewer's upper lid (wave lines only); unset: none
  std::string flare_model = "drawn";  // drawn (fixed per viewer) or wave (glare/wave_lines.hpp)
  bool lens_yellowing = false;        // the lens's density by age (glare/lens_density.hpp)
  bool pupil_from_gaze = false;       // the recorded pupil drives the optics
  double gaze_pupil_scale_mm = 0.0;   // EyeLink: mm per unit of its pupil column
  std::string glare_engine = "exact"; // Vos PSF: exact (full-resolution FFT) or split (tail at reduced resolution)
  int glare_tail_factor = 4;          // the split engine's reduction of the tail
  double glare_resolution = 1.0;      // the convolution's px/deg over the frame's (the light kept in a pixel stays sharp)
  std::string glare_mode = "full";    // full: the eye, everything through the PSF; excess: the light above the display peak
  double display_peak_cd_m2 = 100.0;  // L_dmax (docs/model.md)

  // Retina state (per-cone bleaching and calcium on a retina-fixed grid).
  retina::PhotoreceptorParams receptors;
  bool bleaching_afterimages = true;
  bool adaptation_afterimages = true;
  double state_sites_per_pixel = 0.25;         // retinal grid resolution (1: one site per frame pixel)
  // The grid is raised to this many sites per degree (at the frame's
  // centre), up to half a site per pixel; 0: no floor.
  double state_least_sites_per_deg = 20.0;
  std::string precision = "float";             // state precision: float or double
  double substep_tolerance_deg = 0.05;         // gaze samples closer than this share one state step; 0: every sample
  double afterimage_spread_deg2_per_s = 0.01;  // softening of afterimages: sigma^2 grows at this rate
  // Afterimage visibility fall-off with eccentricity (Jacobs et al. 2015 sec. 2.4); 0: none.
  double afterimage_fovea_sigma_deg = 10.0;
  std::string state_exr;                       // write the state of frame state_frame here
  std::int64_t state_frame = 0;

  // Mesopic vision.
  bool mesopic = true;
  retina::MesopicParams mesopic_colour;
  bool acuity_loss = true;
  retina::AcuityParams acuity;

  // Display.
  retina::EncodingParams encoding;

  // Report.
  std::string report;               // per-frame CSV; a JSON summary and PNG charts go beside it
  double veil_exclusion_deg = 1.0;  // light within this angle of the gaze is not counted as veil
  std::string target_rect;          // X,Y,W,H of the visibility target (target_region.hpp)
  std::string target_mask;          // or its mask image, sequence or folder

  // Preview (preview.hpp, viewer_panels.hpp).
  std::string viewers;        // comma-separated ages or viewer JSON files, rendered side by side
  bool side_by_side = false;  // a plain tone-curve panel of the input before the simulated ones
  bool labels = false;        // panel labels (always on with several panels)
  bool gaze_overlay = false;  // a marker at the gaze, hidden during blinks
  bool timecode = false;      // frame number and time

  // Chunks (chunk_plan.hpp): write only frames [start_frame, end_frame)
  // after processing preroll_s seconds of frames before them unwritten.
  std::int64_t start_frame = 0;
  std::int64_t end_frame = 0;  // 0: to the end
  double preroll_s = 0.0;

  // Checkpoints (checkpoint.hpp).
  std::string checkpoint;            // file
  std::int64_t checkpoint_every = 0;  // frames; 0: none
  bool resume = false;

  // Program.
  std::string quality = "balanced";  // a named bundle of the knobs above (quality_presets.hpp)
  bool print_plan = false;
  bool skip = true;  // scene-adaptive activation of stages (--no-skip: off)
  int threads = 0;  // 0: all cores
  std::int64_t seed = 0;
  bool progress = true;
  double progress_every_s = 10.0;  // between plain progress lines when stderr is not a terminal
  bool quiet = false;              // no progress and no summary line
  bool overwrite = false;          // replace existing outputs (-y)
  std::string progress_file;       // key=value progress blocks for programs (progress.hpp)
  bool verbose = false;
};

class ParamSet;

// Declares every tunable field of `s` (name, unit, range, help; default =
// the field's current value).
ParamSet run_parameters(Settings& s);

}  // namespace eyestream::pipeline
