#include "pipeline/bench/bench_scene.hpp"

#include <filesystem>

#include "io/gaze_import.hpp"
#include "io/source_factory.hpp"
#include "pipeline/bench/scratch_folder.hpp"
#include "samples/scene.hpp"

namespace eyestream::pipeline {

BenchScene load_bench_scene(const std::string& scene, int width, int height, int frames, double luminance_cd_m2) {
  const ScratchFolder dir;
  return load_bench_scene_in(dir.path(), scene, width, height, frames, luminance_cd_m2);
}

BenchScene load_bench_scene_in(const std::filesystem::path& dir, const std::string& scene, int width, int height,
                               int frames, double luminance_cd_m2) {
  constexpr double kFps = 30.0;
  samples::SceneOptions o;
  o.out_dir = dir.string();
  o.width = width;
  o.height = height;
  o.fps = kFps;
  o.duration_s = frames / kFps;
  o.luminance_cd_m2 = luminance_cd_m2;
  samples::find_scene(scene).generate(o);

  BenchScene b;
  b.name = scene;
  const auto source = io::open_source((dir / "frames").string(), io::SourceOptions{});
  b.info = source->info();
  io::GazeImportOptions g;
  g.frame_width = width;
  g.frame_height = height;
  b.gaze = io::read_gaze((dir / "gaze.csv").string(), g);
  while (auto f = source->next()) {
    f->rgb = f->rgb.clone();
    b.frames.push_back(std::move(*f));
  }
  for (size_t i = 0; i < b.frames.size(); ++i) {
    const double t1 = i + 1 < b.frames.size() ? b.frames[i + 1].time_s : b.frames[i].time_s + 1.0 / kFps;
    b.ends_s.push_back(t1);
  }
  return b;
}

}  // namespace eyestream::pipeline
