// The input of one `eyestream bench` case: a built-in scene rendered at a
// given size and held in memory, so reading files is not timed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io/frame.hpp"
#include "io/frame_source.hpp"
#include "io/gaze_sample.hpp"

namespace eyestream::pipeline {

struct BenchScene {
  std::string name;  // as `eyestream sample` knows it
  io::SourceInfo info;
  std::vector<io::SceneFrame> frames;
  std::vector<io::GazeSample> gaze;  // the scene's whole gaze log
  std::vector<double> ends_s;        // where each frame's interval ends
};

// Renders `frames` frames of the scene at width x height and 30 fps (the
// scene's story compressed into them) in a scratch folder, loads them and
// its gaze log, and removes the folder. `luminance_cd_m2` as for `sample`.
BenchScene load_bench_scene(const std::string& scene, int width, int height, int frames,
                            double luminance_cd_m2 = 0.0);

// The same, rendered into `dir` (dir/frames/00000.exr on, dir/gaze.csv),
// which is kept: for programs other than eyestream to read.
BenchScene load_bench_scene_in(const std::filesystem::path& dir, const std::string& scene, int width, int height,
                               int frames, double luminance_cd_m2 = 0.0);

}  // namespace eyestream::pipeline
