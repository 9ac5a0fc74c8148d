// A smooth standard-normal random field over space and time: independent
// N(0,1) values on a coarse grid (a hash of seed, stream and grid node, so
// any thread computes the same), interpolated with smoothstep weights and
// renormalised so every point is again N(0,1) (Jacobs et al. 2015 sec. 2.3.3: "draw
// samples X at a lower spatial and temporal resolution than the scene and
// interpolate").
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

#include "retina/hash_random.hpp"

namespace eyestream::retina {

struct SmoothNoiseParams {
  double cell_px = 32.0;   // grid spacing in pixels
  double period_s = 0.25;  // grid spacing in time
  double clip = 2.0;       // values are clipped to [-clip, clip]
};

// The field on a width x height frame at time t_s (CV_32F); pixel (x, y)
// takes the field's value at (x - origin.x, y - origin.y), so a moving
// origin (the gaze) carries the pattern with it.
cv::Mat smooth_noise(cv::Size size, double t_s, const SmoothNoiseParams& p, std::uint64_t seed, RandomStream stream,
                     cv::Point2d origin = {0.0, 0.0});

}  // namespace eyestream::retina
