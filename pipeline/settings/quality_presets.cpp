#include "pipeline/settings/quality_presets.hpp"

#include "io/error.hpp"

namespace eyestream::pipeline {

void apply_quality_preset(const std::string& name, Settings& s) {
  if (name == "reference") {
    s.precision = "double";
    s.state_sites_per_pixel = 1.0;
    s.state_least_sites_per_deg = 0.0;
    s.substep_tolerance_deg = 0.0;
    s.psf_model = "vos";
    s.glare_engine = "exact";
    s.glare_tail_factor = 4;  // unused by the exact engine; set so presets apply in any order alike
    s.glare_resolution = 1.0;
    s.acuity.pyramid_from_px = 0.0;
    s.sink.video.preset = "medium";
    s.sink.video.b_frames = -1;
    s.sink.video.lookahead = -1;
    s.sink.video.sliced_threads = false;
  } else if (name == "balanced") {
    s.precision = "float";
    s.state_sites_per_pixel = 0.25;
    s.state_least_sites_per_deg = 20.0;  // 0.31 site/px at 1080p, 0.47 at 720p, 0.5 below (docs/model.md)
    s.substep_tolerance_deg = 0.05;
    s.psf_model = "vos";
    s.glare_engine = "split";
    s.glare_tail_factor = 2;
    s.glare_resolution = 1.0;
    s.acuity.pyramid_from_px = 2.5;  // docs/performance.md: 6 px until 2026-12-05
    s.sink.video.preset = "veryfast";  // docs/performance.md: 63 MB less memory and 22 ms less CPU a 1080p frame than faster
    s.sink.video.b_frames = 0;         // docs/performance.md: x264 holds fewer frames
    s.sink.video.lookahead = 5;        // docs/performance.md: 30 MB less, PSNR 0.04 dB lower (veryfast: 10)
    s.sink.video.sliced_threads = true;  // docs/performance.md: 21 MiB less, PSNR the same, the file 0.7 % larger
  } else if (name == "fast") {
    s.precision = "float";
    s.state_sites_per_pixel = 0.25;
    s.state_least_sites_per_deg = 0.0;
    s.substep_tolerance_deg = 0.25;
    s.psf_model = "vos";
    s.glare_engine = "split";
    s.glare_tail_factor = 4;
    s.glare_resolution = 0.5;
    s.acuity.pyramid_from_px = 1.2;  // docs/performance.md: 1.5 px until 2026-12-05 (1.0 raised 720p night-city p99 past 3)
    s.sink.video.preset = "ultrafast";  // docs/performance.md: 34 ms less CPU a 1080p frame than veryfast, PSNR 52 dB
    s.sink.video.b_frames = -1;         // (ultrafast makes none)
    s.sink.video.lookahead = -1;        // (ultrafast looks none ahead)
    s.sink.video.sliced_threads = false;
  } else {
    throw UsageError("--quality: '" + name + "' is not one of reference|balanced|fast");
  }
}

}  // namespace eyestream::pipeline
