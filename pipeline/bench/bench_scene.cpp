#include "pipeline/bench/bench_scene.hpp"

#include <filesystem>
#include <unistd.h>

#include "io/gaze_import.hpp"
#include "io/source_factory.hpp"
#include "samples/scene.hpp"

namespace eyestream::pipeline {

namespace {

// A scratch folder removed when it goes out of scope.
struct Scratch {
  Scratch() {
    static int counter = 0;
    path = std::filesystem::temp_directory_path() /
           ("eyestream-bench-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~Scratch() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  std::filesystem::path path;
};

}  // namespace

BenchScene load_bench_scene(const std::string& scene, int width, int height, int frames, double luminance_cd_m2) {
  constexpr double kFps = 30.0;
  const Scratch dir;
  samples::SceneOptions o;
  o.out_dir = dir.path.string();
  o.width = width;
  o.height = height;
  o.fps = kFps;
  o.duration_s = frames / kFps;
  o.luminance_cd_m2 = luminance_cd_m2;
  samples::find_scene(scene).generate(o);

  BenchScene b;
  b.name = scene;
  const auto source = io::open_source((dir.path / "frames").string(), io::SourceOptions{});
  b.info = source->info();
  io::GazeImportOptions g;
  g.frame_width = width;
  g.frame_height = height;
  b.gaze = io::read_gaze((dir.path / "gaze.csv").string(), g);
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
