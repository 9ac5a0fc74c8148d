// The quality presets against the reference mode (quality_presets.hpp):
// each stays within its documented error bound on the built-in scenes, and
// no preset's output depends on the thread count.
#include <gtest/gtest.h>

#include <iostream>

#include "pipeline/bench/bench_case.hpp"
#include "pipeline/bench/bench_scene.hpp"
#include "pipeline/settings/quality_presets.hpp"
#include "pipeline/bench/reference_error.hpp"
#include "tests/test_support.hpp"

namespace eyestream::pipeline {
namespace {

Settings preset(const std::string& name) {
  Settings s;
  apply_quality_preset(name, s);
  return s;
}

struct Bound {
  std::string preset;
  double de_p99;
};

// The documented bounds (quality_presets.hpp) on 24 frames of the night
// drive, the dusk scene and the night city at 256x144. Measured (flare
// lines on; the split engine draws the tail's lines at its reduced
// resolution; the middle band sharpened since the second session of
// 2026-12-05): balanced p99 0.75 (night drive), 1.18 (dusk), 0.94 (night
// city), its retina grid at the floor's cap of 0.5 site per pixel on these
// 9 px/deg frames (at 0.35 the dusk scene gave 1.71); fast 0.99, 2.36 and
// 1.53 (before the sharpening: balanced 0.86, 1.18, 1.05; fast 1.02, 2.36,
// 1.57).
TEST(QualityPresets, EachPresetStaysWithinItsErrorBoundAgainstReference) {
  for (const std::string scene_name : {"night-drive", "dusk", "night-city"}) {
    if (test::kSanitized && scene_name != "night-city") continue;  // the one with most lights, under ASan
    const BenchScene scene = load_bench_scene(scene_name, 256, 144, 24);
    const BenchCase reference = run_bench_case(scene, preset("reference"));
    for (const Bound& b : {Bound{"balanced", kBalancedDe2000P99}, Bound{"fast", kFastDe2000P99}}) {
      const ReferenceError e = error_against(reference, run_bench_case(scene, preset(b.preset)));
      EXPECT_LE(e.de_p99, b.de_p99) << scene_name << ", " << b.preset;
      std::cout << scene_name << ", " << b.preset << ": p99 CIEDE2000 " << e.de_p99 << "\n";
      EXPECT_GT(e.de_max, 0.0) << scene_name << ", " << b.preset << " differs from reference somewhere";
    }
  }
}

TEST(QualityPresets, OutputDoesNotDependOnTheThreadCount) {
  const BenchScene scene = load_bench_scene("night-drive", 160, 90, 8);
  const int threads = cv::getNumThreads();
  for (const std::string name : {"reference", "balanced", "fast"}) {
    cv::setNumThreads(1);
    const BenchCase one = run_bench_case(scene, preset(name));
    cv::setNumThreads(2);
    const BenchCase two = run_bench_case(scene, preset(name));
    for (size_t i = 0; i < one.shown.size(); ++i)
      EXPECT_EQ(cv::norm(one.shown[i], two.shown[i], cv::NORM_INF), 0.0) << name << ", frame " << i;
  }
  cv::setNumThreads(threads);
}

}  // namespace
}  // namespace eyestream::pipeline
