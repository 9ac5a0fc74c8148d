#include "io/error.hpp"
#include "samples/night_drive.hpp"
#include "samples/scene.hpp"

namespace eyestream::samples {

const std::vector<Scene>& scenes() {
  static const std::vector<Scene> all = {
      {"night-drive",
       "a night road with street lamps and an oncoming car whose headlights grow from distant points to 1e5 "
       "cd/m^2; the gaze follows the road, glances at the headlights and blinks once",
       kNightDriveDuration_s, generate_night_drive},
  };
  return all;
}

const Scene& find_scene(const std::string& name) {
  std::string names;
  for (const Scene& s : scenes()) {
    if (s.name == name) return s;
    names += (names.empty() ? "" : ", ") + s.name;
  }
  throw UsageError("sample: unknown scene '" + name + "' (scenes: " + names + ")");
}

}  // namespace eyestream::samples
