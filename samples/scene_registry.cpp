#include "io/error.hpp"
#include "samples/adaptation_scene.hpp"
#include "samples/dappled_sunlight.hpp"
#include "samples/dusk.hpp"
#include "samples/flash.hpp"
#include "samples/headlights.hpp"
#include "samples/night_drive.hpp"
#include "samples/night_city.hpp"
#include "samples/night_drive_long.hpp"
#include "samples/scene.hpp"
#include "samples/shaped_lamps.hpp"

namespace eyestream::samples {

const std::vector<Scene>& scenes() {
  static const std::vector<Scene> all = {
      {"night-drive",
       "a night road with street lamps and an oncoming car whose headlights grow from distant points to 1e5 "
       "cd/m^2; the gaze follows the road, glances at the headlights and blinks once",
       kNightDriveDuration_s, generate_night_drive},
      {"night-drive-long",
       "20 s on the night road: an oncoming car closing from 450 m to 12 m (headlight illuminance at the eye 0.025 "
       "to 35 lx), a pedestrian on the verge (target masks in DIR/target), the gaze moving between road, pedestrian "
       "and headlights with five blinks",
       kNightDriveLongDuration_s, generate_night_drive_long},
      {"night-city",
       "a city street at night: lit windows, neon signs, sodium and LED street lamps (3e4-4e4 cd/m^2), traffic "
       "signals and two cars' headlights and tail lights, hundreds of lights above a display's peak; the gaze "
       "wanders in fixations and saccades, with a blink",
       kNightCityDuration_s, generate_night_city},
      {"dappled-sunlight",
       "looking up into a tree with the sun (--luminance, default 1.6e9 cd/m^2) through 24 gaps among leaves lit "
       "from behind; each gap's light follows its own 1/f chaos fluctuation and the gaps sway in the wind "
       "(Matsuda and Ikedo eqs. 9-11): glare that flickers and moves",
       kDappledSunlightDuration_s, generate_dappled_sunlight},
      {"shaped-lamps",
       "lights that are not points and do not stand still, on a dark street: an elongated LED street lamp (1.5 by "
       "0.08 deg, 2e4 cd/m^2), an amber beacon whose beam sweeps past the eye 1.5 times a second (1e6 cd/m^2 on "
       "its axis), a cyclist's lamp crossing at 4 deg/s",
       kShapedLampsDuration_s, generate_shaped_lamps},
      {"flash",
       "a 1/8 s neutral flash (--luminance, default 1e7 cd/m^2) of 2 deg radius on black at 0.5 s, then darkness; "
       "gaze fixed on it: bleaching afterimages and the flight of colours",
       kFlashDuration_s, generate_flash},
      {"adaptation",
       "10 s fixation between a 1000 cd/m^2 white patch and a saturated blue patch on 100 cd/m^2 grey, then "
       "uniform grey: local-adaptation afterimages (dark, and yellowish)",
       kAdaptationDuration_s, generate_adaptation},
      {"dusk",
       "a colour checker and a bar resolution target under light fading from 1e3 cd/m^2 white (--luminance) to "
       "1e-2 and back over 24 s, gaze wandering over them: mesopic colour and acuity loss",
       kDuskDuration_s, generate_dusk},
      {"headlights",
       "a still night view: two 1e5 cd/m^2 headlights (--luminance) 1.4 deg apart on a 0.3 cd/m^2 road and a "
       "0.6 cd/m^2 pedestrian 4 deg to their left (target masks in DIR/target), gaze on the pedestrian: glare and "
       "visibility",
       kHeadlightsDuration_s, generate_headlights},
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
