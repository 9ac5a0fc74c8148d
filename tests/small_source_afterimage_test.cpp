// A small bright flash leaves the same afterimage at every resolution and
// preset. The eye's optics make it so: no 0.1 deg source reaches the retina
// as a 0.1 deg disk; the PSF's core and corona spread a 1e7 cd/m^2 light
// over far more than a retina site, and the afterimage of that retinal
// image does not depend on how finely the grid samples it. (With the
// optics off, --no-glare, a source smaller than a site bleaches the whole
// site at its diluted intensity: the integral then varies several times
// across these resolutions; docs/model.md, departures.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "pipeline/eye/eye_simulator.hpp"
#include "pipeline/settings/quality_presets.hpp"
#include "tests/test_support.hpp"

namespace eyestream::pipeline {
namespace {

struct Afterimage {
  double integral_deg2 = 0;  // L-cone bleaching departure integrated over the retina (deg^2)
  double peak = 0;
};

// A disk of `diameter_deg` at 1e7 cd/m^2 flashed for one frame on a dark
// field, then 0.5 s of the dark field; the bleaching departure then.
Afterimage flash_afterimage(double ppd, const std::string& preset, double diameter_deg, bool glare) {
  Settings s;
  apply_quality_preset(preset, s);
  s.glare = glare;
  s.surround_cd_m2 = 0.01;
  const int w = int(std::lround(4.0 * ppd)), h = int(std::lround(3.0 * ppd));
  s.geometry.fov_deg = w / ppd;
  const double fps = 30.0;
  EyeSimulator eye(test::plan_for(s, w, h, fps));
  const cv::Mat dark = test::constant_frame(w, h, {0.01f, 0.01f, 0.01f});
  // The disk, antialiased by 8x8 supersampling, as a renderer draws it.
  cv::Mat flash = dark.clone();
  const double r = 0.5 * diameter_deg * ppd, cx = w / 2.0, cy = h / 2.0;
  for (int y = int(cy - r) - 1; y <= int(cy + r) + 1; ++y)
    for (int x = int(cx - r) - 1; x <= int(cx + r) + 1; ++x) {
      int inside = 0;
      for (int sy = 0; sy < 8; ++sy)
        for (int sx = 0; sx < 8; ++sx) inside += std::hypot(x + (sx + 0.5) / 8 - cx, y + (sy + 0.5) / 8 - cy) <= r;
      flash.at<cv::Vec3f>(y, x) += cv::Vec3f::all(float(1e7 * inside / 64.0));
    }
  const int last = 1 + int(0.5 * fps);
  for (int i = 0; i <= last; ++i) {
    const double t0 = i / fps, t1 = (i + 1) / fps;
    eye.process({i == 1 ? flash : dark, t0, i, "test"}, {{t0, t1, cx, cy, false}});
  }
  bool started = false;
  const std::vector<cv::Mat> state = eye.retina().save(started);  // B, D, B_inf, R, ...
  cv::Mat b[3];
  cv::split(state[0] - state[2], b);
  const double site_deg = 1.0 / (ppd * eye.retina().grid().sites_per_pixel());
  Afterimage a;
  a.integral_deg2 = cv::sum(b[0])[0] * site_deg * site_deg;
  cv::minMaxLoc(b[0], nullptr, &a.peak);
  return a;
}

TEST(SmallSourceAfterimage, IntegralAndPeakDoNotDependOnResolutionOrPreset) {
  for (double diameter : {0.1, 0.3}) {
    double lo_i = 1e30, hi_i = 0, lo_p = 1e30, hi_p = 0;
    for (const char* preset : {"reference", "balanced"})
      for (double ppd : {20.0, 40.0, 80.0}) {
        if (test::kSanitized && ppd == 80.0) continue;  // three quarters of its 94 s under ASan
        const Afterimage a = flash_afterimage(ppd, preset, diameter, true);
        lo_i = std::min(lo_i, a.integral_deg2), hi_i = std::max(hi_i, a.integral_deg2);
        lo_p = std::min(lo_p, a.peak), hi_p = std::max(hi_p, a.peak);
      }
    EXPECT_LT(hi_i / lo_i, 1.15) << diameter << " deg: integral " << lo_i << " to " << hi_i << " deg^2";
    EXPECT_LT(hi_p / lo_p, 1.15) << diameter << " deg: peak " << lo_p << " to " << hi_p;
    std::printf("%g deg: integral %.4g to %.4g deg^2, peak %.4f to %.4f\n", diameter, lo_i, hi_i, lo_p, hi_p);
  }
}

}  // namespace
}  // namespace eyestream::pipeline
