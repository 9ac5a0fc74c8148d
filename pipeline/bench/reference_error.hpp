// How far one run's output and retina state are from another's (the
// reference mode, or the same preset with --no-skip): the error columns of
// `eyestream bench` and the error-bound tests of the quality presets.
#pragma once

#include "pipeline/bench/bench_case.hpp"

namespace eyestream::pipeline {

struct ReferenceError {
  double de_p99 = 0.0;  // 99th percentile of CIEDE2000 over every pixel of every frame (display-linear output)
  double de_max = 0.0;  // its maximum
  // Largest difference of the final retina state, as a fraction of each
  // quantity's full scale (bleached fraction B: 1; calcium deficit D: C_max),
  // the run's grid sampled at the reference's sites.
  double state = 0.0;
};

// `run` against `reference`: same scene, same frame count.
ReferenceError error_against(const BenchCase& reference, const BenchCase& run);

}  // namespace eyestream::pipeline
