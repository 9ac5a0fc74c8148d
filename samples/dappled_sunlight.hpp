// The `dappled-sunlight` scene: looking up into a tree's canopy with the
// sun behind it, after Matsuda and Ikedo's sunlight through leaves (their
// eqs. 9-11). The sun shows through n gaps among the leaves; gap i passes
// I / n * S_i(t) of the sun's light, S_i an independent 1/f chaos orbit
// (chaos_fluctuation.hpp) stepped on a 30 Hz wind clock whatever the frame
// rate, and the gaps sway with the wind (a gust shared by all, smoothed,
// plus each leaf's own). The leaves are lit from behind (green-yellow,
// 100-600 cd/m^2), with patches of sky. The gaze rests on the canopy.
#pragma once

#include <cstdint>
#include <vector>

#include "samples/scene.hpp"

namespace eyestream::samples {

inline constexpr double kDappledSunlightDuration_s = 10.0;
inline constexpr double kSunLuminance_cd_m2 = 1.6e9;  // the sun's disc at noon
inline constexpr int kSunGaps = 24;
inline constexpr double kWindClock_hz = 30.0;

// The light each gap passes at wind step k (0, 1, ...): S_i, for the
// scene's seed; gap i draws sun luminance times S_i over its area.
std::vector<std::vector<double>> sun_gap_fluctuations(std::uint64_t seed, int steps);

void generate_dappled_sunlight(const SceneOptions& options);

}  // namespace eyestream::samples
