// Built-in scenes: procedural HDR sequences in absolute cd/m^2 with a gaze
// log, for the demo, the tests and users trying the program without data.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace eyestream::samples {

struct SceneOptions {
  std::string out_dir;  // receives frames/%05d.exr and gaze.csv
  int width = 640;
  int height = 360;
  double fps = 30.0;
  double duration_s = 0.0;  // 0: the scene's own length
  std::uint64_t seed = 0;
  double luminance_cd_m2 = 0.0;  // the scene's key luminance (e.g. the flash); 0: the scene's own
};

struct Scene {
  std::string name;
  std::string summary;
  double default_duration_s;
  std::function<void(const SceneOptions&)> generate;
};

// All scenes, by name.
const std::vector<Scene>& scenes();
// The scene called `name`; UsageError listing the names if there is none.
const Scene& find_scene(const std::string& name);

}  // namespace eyestream::samples
