#include "pipeline/parameter.hpp"
#include "pipeline/settings.hpp"

namespace eyestream::pipeline {

ParamSet run_parameters(Settings& s) {
  ParamSet set;
  const std::string in = "Input", view = "Viewing condition", eye = "Retina", out = "Output", prog = "Program";
  // Input.
  set.add(number("scale", "cd/m^2 per unit", "luminance of pixel value 1; overrides the EXR whiteLuminance attribute",
                 in, &s.exr.scale, 1e-12, 1e12));
  set.add(number("fps", "1/s", "frame rate; overrides the EXR framesPerSecond attribute (30 when neither says)", in,
                 &s.exr.frames_per_second, 1e-3, 10000));
  set.add(flag("skip-missing", "go on past missing frames of a numbered sequence", in, &s.exr.skip_missing));
  set.add(number("max-pixels", "pixels", "refuse larger frames, before allocating", in, &s.exr.max_pixels, 1, 4e9));
  set.add(choice("gaze-units", "gaze positions in frame pixels (px) or 0..1 of the frame (norm)", in, &s.gaze_units,
                 {"px", "norm"}));
  // Viewing condition.
  set.add(number("fov-deg", "deg", "horizontal field of view of the frame; 0 derives it from the display", view,
                 &s.geometry.fov_deg, 0, 179));
  set.add(number("display-diagonal", "m", "display diagonal; the frame fills the display", view,
                 &s.geometry.display_diagonal_m, 0.01, 100));
  set.add(number("viewing-distance", "m", "eye to display distance", view, &s.geometry.viewing_distance_m, 0.01, 1000));
  set.add(number("surround", "cd/m^2", "luminance seen outside the frame", view, &s.surround_cd_m2, 0, 1e9));
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
  // Output.
  set.add(number("gamma", "", "display value J^gamma", out, &s.encoding.gamma, 0.1, 3));
  set.add(flag("dither", "temporal dithering before quantisation", out, &s.encoding.dither));
  set.add(number("crf", "", "H.264 constant rate factor (lower is better)", out, &s.sink.video.crf, 0, 51));
  set.add(choice("x264-preset", "H.264 encoder speed preset", out, &s.sink.video.preset,
                 {"ultrafast", "superfast", "veryfast", "faster", "fast", "medium", "slow", "slower", "veryslow"}));
  set.add(number("encoder-threads", "", "H.264 encoder threads (fixed: output bytes depend on it)", out,
                 &s.sink.video.encoder_threads, 1, 64));
  set.add(choice("png-bits", "PNG bit depth", out, &s.sink.png_bits, {"8", "16"}));
  // Program.
  set.add(number("threads", "", "worker threads; 0 uses all cores (output never depends on it)", prog, &s.threads, 0,
                 1024));
  set.add(number("seed", "", "seed of every random stream", prog, &s.seed, 0, 9.007199254740992e15));
  set.add(flag("progress", "progress bar on stderr when it is a terminal", prog, &s.progress));
  set.add(flag("verbose", "per-frame log on stderr", prog, &s.verbose));
  return set;
}

}  // namespace eyestream::pipeline
