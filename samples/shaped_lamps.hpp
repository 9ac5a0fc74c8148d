// The `shaped-lamps` scene: lights that are not points and do not stand
// still, on a dark street: an elongated LED street lamp (a bar 1.5 deg by
// 0.08 deg), an amber rotating beacon whose beam sweeps past the viewer
// (a cos^8 lobe turning at 1.5 turns/s), and a cyclist's lamp crossing the
// view at 4 deg/s. The gaze rests between them. For flare lines and halos
// of shaped sources, and glare that moves.
#pragma once

#include "samples/scene.hpp"

namespace eyestream::samples {

inline constexpr double kShapedLampsDuration_s = 6.0;
inline constexpr double kBarLuminance_cd_m2 = 2e4;
inline constexpr double kBarLength_deg = 1.5, kBarWidth_deg = 0.08;
inline constexpr double kBeaconPeak_cd_m2 = 1e6;    // the beam's axis towards the eye
inline constexpr double kBeaconTurns_hz = 1.5;
inline constexpr double kCyclistSpeed_deg_s = 4.0;
inline constexpr double kCyclistLuminance_cd_m2 = 5e4;

// The beacon's luminance at t seconds: its lens glows at 1 % of the peak
// from the side and adds the beam, peak cos^8 of the angle between the
// beam and the eye, when the beam faces the eye (at t = 0, 2/3 s, ...).
double beacon_luminance(double t_s);

void generate_shaped_lamps(const SceneOptions& options);

}  // namespace eyestream::samples
