#include "pipeline/settings/plan.hpp"

#include "glare/lens_density.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "io/error.hpp"
#include "retina/luminance.hpp"

namespace eyestream::pipeline {

Plan compile_plan(const Settings& s, const io::SourceInfo& source) {
  if (!(s.mesopic_colour.bottom_log < s.mesopic_colour.top_log))
    throw UsageError("--mesopic-bottom must be below --mesopic-top");
  if (!(s.tone.plateau_low < s.tone.plateau_high)) throw UsageError("--plateau-low must be below --plateau-high");
  Plan p;
  p.width = source.width;
  p.height = source.height;
  p.frames_per_second = source.frames_per_second;
  p.fov_deg = field_of_view_deg(s.geometry, source.width, source.height);
  p.projection = std::make_shared<const FrameProjection>(source.width, source.height, p.fov_deg,
                                                         projection_from_name(s.geometry.projection));
  p.pixels_per_degree = p.projection->pixels_per_degree();
  p.patch_deg = s.adaptation_patch_deg;
  p.dark_cd_m2 = s.dark_cd_m2;
  p.dark_log = std::log10(s.dark_cd_m2);
  p.surround_from_edge = !s.surround_cd_m2.has_value();
  p.surround_cd_m2 = std::max(s.surround_cd_m2.value_or(1.0), s.dark_cd_m2);
  p.pupil = s.pupil_dynamics;
  p.adaptation = s.adaptation;
  p.tone = s.tone;
  p.encoding = s.encoding;
  p.encoding.seed = std::uint64_t(s.seed);
  // A grid of at least state_least_sites_per_deg, raised no further than
  // half a site per pixel: the afterimages' softening (0.01 deg^2/s)
  // spreads them by 0.05 deg within a quarter second's fixation, so 20
  // sites/deg keep what a fixation leaves; the cap keeps a wide field of
  // view (few px/deg) from asking for a reference-sized grid
  // (docs/model.md).
  constexpr double kMostRaisedSitesPerPixel = 0.5;
  p.retina.sites_per_pixel =
      std::max(s.state_sites_per_pixel,
               std::min(s.state_least_sites_per_deg / p.pixels_per_degree, kMostRaisedSitesPerPixel));
  p.retina.double_precision = s.precision == "double";
  p.retina.substep_tolerance_px = s.substep_tolerance_deg * p.pixels_per_degree;
  p.retina.spread_deg2_per_s = s.afterimage_spread_deg2_per_s;
  p.retina.receptors = s.receptors;
  p.retina.afterimages.bleaching = s.bleaching_afterimages;
  p.retina.afterimages.local_adaptation = s.adaptation_afterimages;
  p.retina.fovea_sigma_px = s.afterimage_fovea_sigma_deg * p.pixels_per_degree;
  p.glare.enabled = s.glare;
  p.glare.full = s.glare_mode == "full";
  p.glare.gaussian = s.psf_model == "gaussian";
  p.glare.tail_factor = s.glare_engine == "exact" ? 1 : s.glare_tail_factor;
  // Never below 20 px/deg: fast's p99 CIEDE2000 on the night city was 1.69
  // with its convolution at 32 px/deg (1080p), 2.16 at 21.5 (720p), 2.47 at
  // 16 and 6.64 at 4.4 (the halo's rings and the core need the pixels).
  constexpr double kLeastPlanePpd = 20.0;
  p.glare.plane_scale = std::clamp(std::max(s.glare_resolution, kLeastPlanePpd / p.pixels_per_degree), 0.0, 1.0);
  p.glare.display_peak_cd_m2 = s.display_peak_cd_m2;
  p.glare.model = s.psf_model == "cie" ? glare::PsfModel::cie : glare::PsfModel::vos;
  if (s.flare_model == "wave" && s.psf_model == "gaussian")
    throw UsageError("--flare-model wave lays its lines over an eye's PSF (--psf-model vos or cie), not the Gaussian");
  p.glare.wave_lines = s.flare_lines && s.flare_model == "wave";
  if (s.eyelid_mrd1_mm && !p.glare.wave_lines)
    throw UsageError("--eyelid-mrd1 draws the lid and its lashes into the wave-optics aperture: it needs "
                     "--flare-model wave (with --flare-lines)");
  p.glare.flare_lines = s.flare_lines && !p.glare.wave_lines;
  if (s.lens_yellowing) {
    p.lens_filter = glare::lens_filter_rgb(s.viewer.age_years);
    // A surround given in cd/m^2 reaches the retina through the same lens
    // (one taken from the frame's edge already has).
    const cv::Vec3f white = *p.lens_filter * cv::Vec3f(1, 1, 1);
    if (!p.surround_from_edge) p.surround_cd_m2 *= double(retina::photopic_luminance(white));
  }
  p.pupil_from_gaze = s.pupil_from_gaze;
  p.glare.viewer = s.viewer;
  p.glare.viewer.eyelid_mrd1_mm = s.eyelid_mrd1_mm.value_or(0.0);
  p.glare.viewer.pupil =
      s.pupil_model == "watson-yellott" ? glare::PupilModel::watson_yellott : glare::PupilModel::moon_spencer;
  p.mesopic.enabled = s.mesopic;
  p.mesopic.colour = s.mesopic_colour;
  p.mesopic.acuity = s.acuity_loss;
  p.mesopic.acuity_params = s.acuity;
  p.skip = s.skip;
  p.report = !s.report.empty();
  p.veil_exclusion_deg = s.veil_exclusion_deg;
  return p;
}

namespace {

std::string describe_glare(const GlarePlan& g) {
  std::ostringstream o;
  o << (g.enabled ? (g.full ? "full image, surround scattered in" : "excess over the display peak") : "off");
  if (g.gaussian) {
    o << ", Gaussian kernel (sigma " << g.gaussian_sigma_deg << " deg)";
  } else {
    o << (g.model == glare::PsfModel::cie ? ", CIE 146 scatter with Vos core and halo" : ", Vos PSF")
      << (g.flare_lines ? " with flare lines" : g.wave_lines ? " with wave-optics flare lines" : "");
    if (g.tail_factor > 1)
      o << ", split engine (tail at 1/" << g.tail_factor << " resolution)";
    else
      o << ", exact FFT engine";
    if (g.plane_scale != 1.0) o << ", convolved at " << g.plane_scale << " of the frame's resolution";
  }
  o << ", display peak " << g.display_peak_cd_m2 << " cd/m^2";
  return o.str();
}

std::string describe_viewer(const GlarePlan& g) {
  std::ostringstream o;
  o << "age " << g.viewer.age_years << " years";
  if (g.model == glare::PsfModel::cie) o << ", pigmentation " << g.viewer.pigmentation;
  o << (g.viewer.glasses ? ", glasses" : "") << ", haze " << g.viewer.haze << ", pupil "
    << (g.viewer.pupil == glare::PupilModel::watson_yellott ? "Watson-Yellott" : "Moon-Spencer")
    << ", flare-line seed " << g.viewer.seed;
  if (g.viewer.eyelid_mrd1_mm > 0.0) o << ", upper eyelid " << g.viewer.eyelid_mrd1_mm << " mm above the pupil";
  return o.str();
}

}  // namespace

std::string Plan::describe() const {
  std::ostringstream o;
  o << "eyestream = " << EYESTREAM_VERSION << "\n"
    << "frame = " << width << "x" << height << " at " << frames_per_second << " fps\n"
    << "field of view = " << fov_deg << " deg, " << projection_name(projection->kind()) << " ("
    << pixels_per_degree << " px/deg at the centre"
    << (projection->identity() ? std::string()
                               : ", angle plane " + std::to_string(plane_size().width) + "x" +
                                     std::to_string(plane_size().height))
    << ")\n"
    << "adaptation patch = " << patch_deg << " deg\n"
    << "adaptation rates = +" << adaptation.rate_up_log_per_s << " / -" << adaptation.rate_down_log_per_s
    << " log10/s\n"
    << "glare = " << describe_glare(glare) << "\n"
    << "viewer = " << describe_viewer(glare) << "\n"
    << "lens = "
    << (lens_filter ? "yellowed for " + std::to_string(int(std::lround(glare.viewer.age_years))) +
                          " years (Pokorny et al. 1987), blue channel kept " +
                          std::to_string(int(std::lround(100.0 * (*lens_filter)(2, 2)))) + " %"
                    : std::string("the standard observer's"))
    << "\n"
    << "retina state = " << retina.sites_per_pixel << " sites/px (" << retina.sites_per_pixel * pixels_per_degree
    << " sites/deg at the centre), " << (retina.double_precision ? "double" : "float")
    << ", sub-step tolerance " << retina.substep_tolerance_px << " px\n"
    << "afterimages = " << (retina.afterimages.bleaching ? "bleaching" : "no bleaching") << ", "
    << (retina.afterimages.local_adaptation ? "local adaptation" : "no local adaptation") << "\n"
    << "mesopic = " << (mesopic.enabled ? "on" : "off") << " (rho from " << mesopic.colour.bottom_log << " to "
    << mesopic.colour.top_log << " log10 cd/m^2; acuity loss " << (mesopic.acuity ? "on" : "off") << ")\n"
    << "surround = "
    << (surround_from_edge ? "the geometric mean of the frame's outer 1 deg band, frame by frame"
                           : std::to_string(surround_cd_m2) + " cd/m^2")
    << "\n"
    << "pupil = " << (pupil_from_gaze ? "as the gaze log recorded it (the model's beside it in the report); " : "")
    << "follows the field luminance, constricting with tau " << pupil.constrict_tau_s
    << " s, dilating with tau " << pupil.dilate_tau_s << " s\n"
    << "stages = "
    << (glare.enabled ? (glare.full ? "glare (every frame but a uniform field or a still frame under the same optics), "
                                    : "glare (frames with light above the display peak), ")
                      : "")
    << "adaptation, retina, tone curve, mesopic (below 7.5 cd/m^2 of adaptation), afterimages, display encoding"
    << (encoding.dither ? " (dithered)" : "") << "\n"
    << "skipping = "
    << (skip ? "on (glare on a uniform field or a still frame; retina and afterimages at rest; acuity loss "
               "where no band can be lost)"
             : "off (--no-skip: every stage runs on every frame)")
    << "\n";
  return o.str();
}

}  // namespace eyestream::pipeline
