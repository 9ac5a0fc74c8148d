// One case of `eyestream bench`: a scene through one setting, timed per
// stage, with its outputs and final retina state kept for the error
// against the reference (reference_error.hpp).
#pragma once

#include <vector>

#include "pipeline/bench/bench_scene.hpp"
#include "pipeline/settings/settings.hpp"
#include "pipeline/eye/stage_activity.hpp"

namespace eyestream::pipeline {

struct BenchCase {
  StageTimes stage_ms;      // mean per frame
  double filter_ms = 0.0;   // mean per frame, every stage of the eye
  double encode_ms = 0.0;   // mean per frame, 8-bit dithered display encoding
  double wall_ms = 0.0;     // mean per frame, the whole of the eye's process() and the encoding, by the clock
  double setup_s = 0.0;     // plan, kernels and spectra, before the first frame
  double memory_mib = 0.0;  // peak resident memory above what the process held before the case
  int frames = 0;
  // Frames on which each stage worked.
  int glare_frames = 0, retina_frames = 0, afterimage_frames = 0, mesopic_frames = 0, acuity_frames = 0;
  // Frames at rest (no glare, retina or afterimage work: a still frame once
  // its state has settled) and their mean filter time.
  int rest_frames = 0;
  double rest_ms = 0.0;
  std::vector<cv::Mat> shown;  // display-linear output of every frame
  cv::Mat bleached, deficit;   // the retina state after the last frame
  double sites_per_pixel = 1.0, calcium_max = 1.0;
};

// Runs every frame of `scene` through an eye with `settings` (threads as
// cv::setNumThreads was left) and encodes each output as a sink would,
// after one untimed frame through another eye (the first frame of a
// process pays for growing the buffer pool).
BenchCase run_bench_case(const BenchScene& scene, const Settings& settings);

}  // namespace eyestream::pipeline
