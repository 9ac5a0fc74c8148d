// Which stages did work on a frame and how long each took: the scene-
// adaptive activation of the quality presets (quality_presets.hpp) made
// visible to logs, reports and `eyestream bench`.
#pragma once

#include <chrono>

namespace eyestream::pipeline {

struct StageActivity {
  bool glare = false;        // the glare was computed on this frame
  bool glare_reused = false; // the last frame's glare was reused (a still frame): glare is in the picture
  bool retina = false;       // the photoreceptor state was stepped (not at rest on an unchanged stimulus)
  bool afterimages = false;  // afterimages were drawn (the retina was not at rest)
  bool mesopic = false;      // mesopic colour (adaptation below the photopic limit)
  bool acuity = false;       // stochastic acuity loss (some band could be lost)
};

// Wall time of each stage on one frame, in milliseconds.
struct StageTimes {
  double glare_ms = 0, adaptation_ms = 0, retina_ms = 0, mesopic_ms = 0, afterimage_ms = 0;
  double total() const { return glare_ms + adaptation_ms + retina_ms + mesopic_ms + afterimage_ms; }
  StageTimes& operator+=(const StageTimes& o) {
    glare_ms += o.glare_ms, adaptation_ms += o.adaptation_ms, retina_ms += o.retina_ms;
    mesopic_ms += o.mesopic_ms, afterimage_ms += o.afterimage_ms;
    return *this;
  }
  StageTimes& operator*=(double k) {
    glare_ms *= k, adaptation_ms *= k, retina_ms *= k, mesopic_ms *= k, afterimage_ms *= k;
    return *this;
  }
};

// Milliseconds since `start`, and restarts it.
inline double lap_ms(std::chrono::steady_clock::time_point& start) {
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - start).count();
  start = now;
  return ms;
}

}  // namespace eyestream::pipeline
