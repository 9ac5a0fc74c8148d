#include <cctype>

#include "pipeline/settings/parameter.hpp"
#include "pipeline/settings/settings.hpp"

namespace eyestream::pipeline {

ParamSet run_parameters(Settings& s) {
  ParamSet set;
  const std::string in = "Input", view = "Viewing condition", eye = "Retina", out = "Output", prog = "Program";
  // Input.
  set.add(number("scale", "cd/m^2 per unit", "luminance of pixel value 1; overrides the EXR whiteLuminance attribute",
                 in, &s.exr.scale, 1e-12, 1e12));
  set.add(number("fps", "1/s", "frame rate; overrides the EXR framesPerSecond attribute (30 when neither says)", in,
                 &s.exr.frames_per_second, 1e-3, 10000));
  set.add(text("layer", "layer of layered EXRs (Blender's ViewLayer.Combined); default the beauty pass", in,
               &s.exr.layer));
  set.add(flag("skip-missing", "go on past missing frames of a numbered sequence", in, &s.exr.skip_missing));
  Param max_pixels = number("max-pixels", "pixels", "refuse larger frames, before allocating", in, &s.exr.max_pixels, 1, 4e9);
  max_pixels.shown_default = "the machine's memory over 400 bytes a pixel";
  set.add(max_pixels);
  set.add(choice("on-bad-video", "a video packet that does not decode, a video that ends early, or raw input ending "
                 "inside a frame: fail, or stop there keeping what was read", in, &s.video_input.on_bad_video,
                 {"fail", "stop"}));
  set.add(text("size", "WxH of raw float RGB frames on standard input (-i -)", in, &s.frame_size));
  set.add(choice("video-transfer", "transfer of a video input: auto (its PQ or HLG tag), pq, hlg, or sdr (BT.1886)",
                 in, &s.video_input.transfer, {"auto", "pq", "hlg", "sdr"}));
  set.add(number("video-peak", "cd/m^2", "nominal peak of an HLG video (0: 1000) or white of an SDR one (0: 100)", in,
                 &s.video_input.peak_cd_m2, 0, 1e5));
  set.add(choice("gaze-units", "gaze positions in frame pixels (px) or 0..1 of the frame (norm)", in, &s.gaze_units,
                 {"px", "norm"}));
  set.add(choice("bad-pixels", "NaN or infinite pixels: clamp (shown black, counted) or fail", in, &s.bad_pixels,
                 {"clamp", "fail"}));
  set.add(choice("gaze-format", "gaze log format; auto detects it from the header", in, &s.gaze_format,
                 {"auto", "native", "pupil-core", "neon", "neon-surface", "tobii", "eyelink"}));
  set.add(text("gaze-recording", "Neon, Tobii: the recording to read when the export holds several", in,
               &s.gaze_recording));
  set.add(text("gaze-blinks",
               "Pupil Core, Neon: auto reads the blinks.csv beside the export, none reads no blinks, or the path of "
               "a blinks file",
               in, &s.gaze_blinks));
  set.add(text("gaze-pupils",
               "Pupil Core, Neon, with --pupil-from-gaze: auto reads the pupil_positions.csv or 3d_eye_states.csv "
               "beside the export, none reads none, or the path of one",
               in, &s.gaze_pupils));
  set.add(number("gaze-pupil-scale", "mm",
                 "EyeLink: millimetres per unit of pupil diameter, or per square root of a unit of pupil area "
                 "(PUPIL AREA files, EyeLink's default); 0: the pupil is not read",
                 in, &s.gaze_pupil_scale_mm, 0, 100));
  set.add(choice("gaze-eye", "EyeLink binocular files: the left or right eye, or their average", in, &s.gaze_eye,
                 {"average", "left", "right"}));
  set.add(number("gaze-offset", "s", "added to every gaze time (after sync)", in, &s.gaze_offset_s, -1e6, 1e6));
  set.add(number("gaze-sync", "s", "export clock at the first frame (exports only; default: the first sample)", in,
                 &s.gaze_sync_s, -1e12, 1e12));
  set.add(text("gaze-sync-message", "EyeLink: the first MSG line holding this text (a stimulus onset) is the first frame",
               in, &s.gaze_sync_message));
  set.add(number("gaze-confidence", "", "Pupil Core gaze samples below this confidence count as lost, and pupil samples as missing", in,
                 &s.gaze_confidence, 0, 1));
  set.add(number("gaze-source-width", "px", "width of the export's scene camera or screen; 0: the format's own", in,
                 &s.gaze_source_width, 0, 100000));
  set.add(number("gaze-source-height", "px", "height of the export's scene camera or screen; 0: the format's own", in,
                 &s.gaze_source_height, 0, 100000));
  // Viewing condition.
  set.add(number("fov-deg", "deg", "horizontal field of view of the frame; 0 derives it from the display", view,
                 &s.geometry.fov_deg, 0, 179));
  set.add(choice("projection",
                 "how the frame maps to directions: rectilinear (renderers, simulators, a flat display) or "
                 "equidistant (angle-uniform, fisheye)",
                 view, &s.geometry.projection, {"rectilinear", "equidistant"}));
  set.add(number("display-diagonal", "m", "display diagonal; the frame fills the display", view,
                 &s.geometry.display_diagonal_m, 0.01, 100));
  set.add(number("viewing-distance", "m", "eye to display distance", view, &s.geometry.viewing_distance_m, 0.01, 1000));
  set.add(number("surround", "cd/m^2",
                 "luminance beyond the frame (a display in a room); unset: the geometric mean of the frame's outer "
                 "1 deg band, frame by frame",
                 view, &s.surround_cd_m2, 0, 1e9));
  // Retina.
  set.add(number("adapt-rate-up", "log10 units/s", "adaptation rate toward brighter (a1)", eye,
                 &s.adaptation.rate_up_log_per_s, 0, 1000));
  set.add(number("adapt-rate-down", "log10 units/s", "adaptation rate toward darker (a2)", eye,
                 &s.adaptation.rate_down_log_per_s, 0, 1000));
  set.add(number("adapt-patch", "deg", "side of the patch around the gaze that sets the adaptation target", eye,
                 &s.adaptation_patch_deg, 0.05, 60));
  set.add(number("tone-exponent", "", "Naka-Rushton exponent n", eye, &s.tone.exponent, 0.1, 3));
  set.add(number("plateau-low", "", "steady response M to darkness", eye, &s.tone.plateau_low, 1e-4, 0.99));
  set.add(number("plateau-high", "", "steady response M to daylight", eye, &s.tone.plateau_high, 1e-4, 0.99));
  set.add(number("plateau-mid", "log10 cd/m^2", "luminance where M is halfway", eye, &s.tone.plateau_mid_log, -8, 10));
  set.add(number("plateau-width", "log10 units", "width of M's rise", eye, &s.tone.plateau_width_log, 0.05, 10));
  set.add(number("dark-luminance", "cd/m^2", "what closed eyes see; floor of all luminances", eye, &s.dark_cd_m2, 1e-12,
                 1));
  // Optics.
  const std::string optics = "Glare (the viewer's optics)";
  set.add(flag("glare", "the eye's point-spread function before the retina", optics, &s.glare));
  set.add(choice("psf-model",
                 "the eye's PSF: vos (Spencer et al. 1995), cie (CIE 146:2002 scatter with age and pigmentation, "
                 "Vos core and halo) or the cheap Gaussian of Yoshida et al. 2008 (gaussian)",
                 optics, &s.psf_model, {"vos", "cie", "gaussian"}));
  set.add(flag("flare-lines", "fine radial streaks in the corona and the halo, fixed per --viewer-seed", optics,
               &s.flare_lines));
  set.add(choice("flare-model",
                 "the flare lines: drawn (a fixed pattern per viewer) or wave (the diffraction of the viewer's pupil, "
                 "lens fibres and particles, after Ritschel et al. 2009: they follow the pupil with its hippus, the "
                 "light's direction and the drifting vitreous, for lights 40 times their surround)",
                 optics, &s.flare_model, {"drawn", "wave"}));
  set.add(number("eyelid-mrd1", "mm",
                 "the upper eyelid's margin this far above the pupil's centre (MRD1: about 4-5 open, 1-2 squinting), "
                 "its edge and lashes in the aperture of --flare-model wave; unset: no lid",
                 optics, &s.eyelid_mrd1_mm, 0.5, 8));
  set.add(choice("glare-engine",
                 "Vos PSF convolution: exact (full-resolution FFT) or split (sharp centre at full resolution, tail "
                 "reduced by --glare-tail-factor)",
                 optics, &s.glare_engine, {"exact", "split"}));
  set.add(number("glare-tail-factor", "", "the split engine's reduction of the PSF's tail", optics,
                 &s.glare_tail_factor, 2, 16));
  set.add(number("glare-resolution", "", "the convolution's pixels per degree over the frame's (at its centre), never "
                 "below 20 px/deg; the light the PSF keeps in a pixel stays sharp at any value", optics, &s.glare_resolution, 0.125, 1));
  set.add(choice("glare-mode",
                 "the whole retinal image through the PSF, the eye (full), or only the light above the display "
                 "peak, for an HDR display that shows the rest (excess)",
                 optics,
                 &s.glare_mode, {"excess", "full"}));
  set.add(
      number("display-peak", "cd/m^2", "peak luminance of the display, L_dmax", view, &s.display_peak_cd_m2, 1, 1e5));
  set.add(number("viewer-age", "years", "the viewer's age: scattered light grows as age^4", optics, &s.viewer.age_years,
                 1, 100));
  set.add(number("viewer-pigmentation", "",
                 "ocular pigmentation p of CIE 146 (0 very dark, 0.5 brown, 1 light, 1.2 very light blue eyes); "
                 "cie model only",
                 optics, &s.viewer.pigmentation, 0, 1.2));
  set.add(flag("pupil-from-gaze",
               "the pupil diameter the eye tracker recorded drives the optics (bridged across blinks); the model's "
               "pupil is reported beside it",
               optics, &s.pupil_from_gaze));
  set.add(flag("lens-yellowing",
               "the lens absorbs short wavelengths by --viewer-age (Pokorny et al. 1987), against a 32-year-old's",
               optics, &s.lens_yellowing));
  set.add(flag("viewer-glasses", "the viewer wears (myopic) glasses: more and longer flare lines", optics,
               &s.viewer.glasses));
  set.add(number("viewer-haze", "", "share of the unscattered light that haze or fog turns into wide bloom", optics,
                 &s.viewer.haze, 0, 0.5));
  set.add(number("viewer-seed", "", "the viewer's flare-line pattern", optics, &s.viewer.seed, 0, 9.007199254740992e15));
  set.add(choice("pupil-model",
                 "pupil from the field's luminance: moon-spencer (Moon and Spencer 1944) or watson-yellott (with age "
                 "and field size)",
                 optics, &s.pupil_model, {"moon-spencer", "watson-yellott"}));
  set.add(number("pupil-constrict-tau", "s", "time constant of the pupil's constriction", optics,
                 &s.pupil_dynamics.constrict_tau_s, 0, 60));
  set.add(number("pupil-dilate-tau", "s", "time constant of the pupil's dilation", optics,
                 &s.pupil_dynamics.dilate_tau_s, 0, 60));
  set.add(number("pupil-field", "deg", "watson-yellott: diameter of the adapting field; 0: the frame's field", optics,
                 &s.viewer.pupil_field_deg, 0, 180));
  // Retina state and afterimages.
  const std::string ai = "Afterimages (retina state)";
  const char* cone[3] = {"l", "m", "s"};
  for (int c = 0; c < 3; ++c) {
    set.add(number(std::string("bleach-rate-") + cone[c], "1/(cd/m^2 s)",
                   std::string("photopigment bleaching rate b1 of ") + char(std::toupper(cone[c][0])) + " cones", ai,
                   &s.receptors.bleach_rate[c], 0, 1));
    set.add(number(std::string("regen-rate-") + cone[c], "1/s",
                   std::string("photopigment regeneration rate b2 of ") + char(std::toupper(cone[c][0])) + " cones", ai,
                   &s.receptors.regen_rate_per_s[c], 1e-6, 1e3));
  }
  set.add(number("calcium-influx", "1/s", "calcium influx rate c1", ai, &s.receptors.calcium_influx_per_s, 1e-6, 1e3));
  set.add(number("calcium-efflux", "1/s", "calcium efflux rate c2", ai, &s.receptors.calcium_efflux_per_s, 1e-6, 1e3));
  set.add(
      number("bleaching-strength", "", "bleaching afterimage strength j1", ai, &s.receptors.bleaching_strength, 0, 10));
  set.add(number("adaptation-strength", "", "adaptation afterimage strength j2 (an exponent)", ai,
                 &s.receptors.adaptation_strength, 0, 5));
  set.add(number("gain-epsilon", "of C_max", "regularises the calcium gain in the dark limit", ai,
                 &s.receptors.gain_epsilon, 1e-6, 1));
  set.add(flag("bleaching-afterimages", "show bleaching afterimages", ai, &s.bleaching_afterimages));
  set.add(flag("adaptation-afterimages", "show local-adaptation afterimages", ai, &s.adaptation_afterimages));
  set.add(number("state-resolution", "sites/px",
                 "retina state sites per frame pixel along each axis (raised to --state-least-density, by that at most to 0.5)", ai,
                 &s.state_sites_per_pixel, 0.0625, 1));
  set.add(number("state-least-density", "sites/deg",
                 "raises --state-resolution to this many sites per degree at the frame's centre, up to 0.5 "
                 "site/px; 0: no floor",
                 ai, &s.state_least_sites_per_deg, 0, 1000));
  set.add(choice("precision", "retina state precision", ai, &s.precision, {"float", "double"}));
  set.add(number("substep-tolerance", "deg", "gaze samples closer than this share one state step; 0: every sample", ai,
                 &s.substep_tolerance_deg, 0, 10));
  set.add(number("afterimage-spread", "deg^2/s", "softening of afterimages (sigma^2 grows at this rate)", ai,
                 &s.afterimage_spread_deg2_per_s, 0, 10));
  set.add(number("afterimage-fovea-sigma", "deg", "afterimage visibility falls off with eccentricity; 0: no fall-off",
                 ai, &s.afterimage_fovea_sigma_deg, 0, 180));
  set.add(text("state-exr", "write the retina state (B, C per cone) of --state-frame to this EXR", ai, &s.state_exr));
  set.add(number("state-frame", "", "frame whose state --state-exr writes", ai, &s.state_frame, 0, 1e12));
  // Mesopic vision.
  const std::string meso = "Mesopic vision";
  set.add(flag("mesopic", "mesopic effects (Purkinje shift, hue shift, acuity loss)", meso, &s.mesopic));
  set.add(number("mesopic-top", "log10 cd/m^2", "adaptation level where vision is fully photopic (m1)", meso,
                 &s.mesopic_colour.top_log, -8, 8));
  set.add(number("mesopic-bottom", "log10 cd/m^2", "adaptation level where vision is fully scotopic (m2)", meso,
                 &s.mesopic_colour.bottom_log, -8, 8));
  set.add(flag("purkinje", "blend photopic and scotopic luminance weights by rho", meso, &s.mesopic_colour.purkinje));
  set.add(flag("hue-shift", "colours drift toward the scotopic tint by rho", meso, &s.mesopic_colour.hue_shift));
  set.add(number("mesopic-local-scale", "deg",
                 "mesopic colour follows the local luminance low-passed at this sigma where it is brighter than the "
                 "adaptation level; 0: the adaptation level alone",
                 meso, &s.mesopic_colour.local_sigma_deg, 0, 10));
  const char* rgb[3] = {"r", "g", "b"};
  for (int c = 0; c < 3; ++c)
    set.add(number(std::string("scotopic-tint-") + rgb[c], "linear",
                   std::string("colour a grey drifts to in the dark (dull purple), channel ") + rgb[c], meso,
                   &s.mesopic_colour.scotopic_tint[c], 0.01, 10));
  set.add(flag("acuity-loss", "stochastic loss of fine detail in low light", meso, &s.acuity_loss));
  set.add(number("acuity-sigma0", "arcmin", "finest band edge; band i ends at sigma0 2^i", meso,
                 &s.acuity.sigma0_arcmin, 0.05, 60));
  set.add(
      number("acuity-noise", "", "variance g of the stochastic acuity thresholds", meso, &s.acuity.noise_gain, 0, 2));
  set.add(number("acuity-cell", "deg", "spatial spacing of the acuity noise grid", meso, &s.acuity.noise_cell_deg, 0.01,
                 30));
  set.add(number("acuity-pyramid-from", "px",
                 "blurs of the acuity bands and of the local mesopic luminance at least this wide run at reduced "
                 "resolution; 0: all at full resolution",
                 meso, &s.acuity.pyramid_from_px, 0, 1e4));
  set.add(number("acuity-period", "s", "temporal spacing of the acuity noise grid", meso, &s.acuity.noise_period_s,
                 0.01, 60));
  // Output.
  set.add(number("gamma", "", "display value J^gamma", out, &s.encoding.gamma, 0.1, 3));
  set.add(flag("dither", "temporal dithering before quantisation", out, &s.encoding.dither));
  set.add(choice("codec", "video codec: h264 (libx264), hevc (libx265); auto: h264 at 8 bits, else hevc", out,
                 &s.sink.video.codec, {"auto", "h264", "hevc"}));
  set.add(choice("bit-depth", "video bit depth (10 needs hevc)", out, &s.sink.video.bit_depth, {"8", "10"}));
  set.add(flag("hdr10", "HDR10 video (hevc, 10-bit, PQ, BT.2020); display white is --display-peak cd/m^2", out,
               &s.sink.video.hdr10));
  set.add(number("hdr10-peak", "cd/m^2", "mastering display peak written with --hdr10 (MaxCLL and MaxFALL are measured from the frames)", out,
                 &s.sink.video.hdr10_peak_cd_m2, 100, 10000));
  set.add(choice("format", "container of a video on standard output (-o -)", out, &s.sink.video.stream_format,
                 {"mkv", "mp4"}));
  set.add(number("keyint", "frames", "longest distance between video keyframes (seeking, cutting)", out,
                 &s.sink.video.keyint, 1, 10000));
  set.add(number("b-frames", "",
                 "most B-frames in a row in a video; -1: the speed preset's (--quality balanced sets 0: x264 holds "
                 "fewer frames)",
                 out, &s.sink.video.b_frames, -1, 16));
  set.add(number("lookahead", "frames",
                 "frames H.264's rate control looks ahead (x264's macroblock tree); -1: the speed preset's "
                 "(--quality balanced sets 5: x264 holds fewer frames)",
                 out, &s.sink.video.lookahead, -1, 250));
  set.add(number("crf", "", "video constant rate factor (lower is better)", out, &s.sink.video.crf, 0, 51));
  set.add(choice("x264-preset", "video encoder speed preset (x264 and x265 names; --quality sets medium, veryfast or ultrafast)", out, &s.sink.video.preset,
                 {"ultrafast", "superfast", "veryfast", "faster", "fast", "medium", "slow", "slower", "veryslow"}));
  set.add(number("encoder-threads", "", "H.264 encoder threads (fixed: output bytes depend on it)", out,
                 &s.sink.video.encoder_threads, 1, 64));
  set.add(flag("sliced-threads",
               "H.264 encoder threads each code a slice of every frame instead of a frame each: x264 holds fewer "
               "frames, the file is a little larger (--quality balanced sets it)",
               out, &s.sink.video.sliced_threads));
  set.add(choice("png-bits", "PNG bit depth", out, &s.sink.png_bits, {"8", "16"}));
  set.add(choice("exr-compression",
                 "EXR frames' lossless compression: zip keeps float output's files about a seventh smaller than none, "
                 "none writes them many times faster (docs/usage.md)",
                 out, &s.sink.exr_compression, {"zip", "zips", "piz", "rle", "none"}));
  // Report.
  const std::string rep = "Report";
  set.add(text("report", "per-frame CSV of adaptation, pupil, veiling luminance and TI; JSON summary beside it", rep,
               &s.report));
  set.add(number("veil-exclusion", "deg", "light this close to the gaze does not count as veil", rep,
                 &s.veil_exclusion_deg, 0, 30));
  set.add(text("target", "X,Y,W,H: the visibility target in frame pixels; the report gives its contrast", rep,
               &s.target_rect));
  set.add(text("target-mask", "the target as a mask image (PNG or TIFF; grey above 127 is the target), or a numbered sequence or folder of one per frame", rep,
               &s.target_mask));
  // Preview.
  const std::string pre = "Preview";
  set.add(text("viewers", "viewers side by side: ages (25,70) or viewer JSON files (young.json,old.json)", pre,
               &s.viewers));
  set.add(flag("side-by-side", "put the input through a plain tone curve beside the simulation", pre,
               &s.side_by_side));
  set.add(flag("labels", "burn in panel labels (always with several panels)", pre, &s.labels));
  set.add(flag("gaze-overlay", "burn in a marker at the gaze, hidden during blinks", pre, &s.gaze_overlay));
  set.add(flag("timecode", "burn in the frame number and time", pre, &s.timecode));
  // Chunks.
  const std::string chunk = "Chunks (eyestream chunks)";
  set.add(number("start-frame", "", "first frame written (0-based position in the input)", chunk, &s.start_frame, 0,
                 1e12));
  set.add(number("end-frame", "", "frame after the last one written; 0: to the end", chunk, &s.end_frame, 0, 1e12));
  set.add(number("preroll", "s", "frames this long before --start-frame are processed, not written", chunk,
                 &s.preroll_s, 0, 1e6));
  // Program.
  set.add(choice("quality", "preset: reference (exact, slow), balanced, fast; single options override it", prog,
                 &s.quality, {"reference", "balanced", "fast"}));
  set.add(flag("skip",
               "skip work a frame does not need (glare with nothing above the display peak, a retina at rest, "
               "acuity loss in photopic light); --no-skip runs every stage",
               prog, &s.skip));
  set.add(flag("print-plan", "print the resolved settings and stages, then stop without writing", prog, &s.print_plan));
  set.add(number("threads", "", "worker threads; 0 uses all cores (output never depends on it)", prog, &s.threads, 0,
                 1024));
  set.add(number("seed", "", "seed of every random stream", prog, &s.seed, 0, 9.007199254740992e15));
  set.add(text("checkpoint", "checkpoint file: written with --checkpoint-every, read with --resume", prog,
               &s.checkpoint));
  set.add(number("checkpoint-every", "frames", "write the complete state every N frames (PNG/EXR outputs); 0: never",
                 prog, &s.checkpoint_every, 0, 1e12));
  set.add(flag("resume", "continue a killed run from --checkpoint (same command otherwise)", prog, &s.resume));
  set.add(flag("progress", "progress on stderr: a bar on a terminal, else a line every --progress-every seconds",
               prog, &s.progress));
  set.add(number("progress-every", "s", "seconds between progress lines when stderr is not a terminal (CI, Slurm)",
                 prog, &s.progress_every_s, 0, 1e6));
  set.add(text("progress-file", "write key=value progress blocks (frame, fps, eta_s, progress=continue|end) here, "
               "as ffmpeg's -progress", prog, &s.progress_file));
  set.add(flag("quiet", "nothing on stderr but warnings and errors (no progress, no summary line)", prog, &s.quiet));
  set.add(flag("verbose", "per-frame log on stderr", prog, &s.verbose));
  set.add(flag("overwrite", "replace outputs that exist (also -y); without it an existing output is refused", prog,
               &s.overwrite));
  return set;
}

}  // namespace eyestream::pipeline
