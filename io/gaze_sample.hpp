// The native gaze model every gaze format maps to.
#pragma once

#include <limits>

namespace eyestream::io {

enum class EyeState {
  kOpen,    // fixation or saccade: the eye sees the frame at (x, y)
  kClosed,  // blink: the eye sees darkness
  kLost,    // tracker lost: hold the last known gaze
};

// One sample; it holds from `t_s` until the next sample (zero-order hold).
struct GazeSample {
  double t_s = 0.0;         // seconds from the first frame
  double x = 0.0, y = 0.0;  // input-frame pixels, origin top-left, pixel centres at +0.5
  EyeState state = EyeState::kOpen;
  // The pupil diameter the tracker recorded (mm); NaN when it has none.
  double pupil_mm = std::numeric_limits<double>::quiet_NaN();
};

// Whether a sample's recorded pupil can drive the optics: an open eye and
// a finite diameter above 0.
inline bool has_usable_pupil(const GazeSample& s) {
  return s.state == EyeState::kOpen && s.pupil_mm > 0.0 && s.pupil_mm < std::numeric_limits<double>::infinity();
}

}  // namespace eyestream::io
