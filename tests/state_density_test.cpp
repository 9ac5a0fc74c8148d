// The retina state's grid is raised to --state-least-density sites per
// degree (balanced: 20), up to half a site per pixel (pipeline/settings/
// plan.cpp). The pixels per degree are
// worked out here from the field of view alone (a rectilinear frame's
// focal length, (W / 2) / tan(fov / 2) px, times pi / 180 at its centre).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pipeline/settings/plan.hpp"
#include "pipeline/settings/quality_presets.hpp"

namespace eyestream::pipeline {
namespace {

Plan plan_for(const std::string& preset, int width, int height, double least = -1.0) {
  Settings s;
  apply_quality_preset(preset, s);
  if (least >= 0.0) s.state_least_sites_per_deg = least;
  io::SourceInfo info;
  info.width = width;
  info.height = height;
  info.frames_per_second = 30;
  return compile_plan(s, info);
}

double centre_ppd(const Plan& p) {
  const double pi = std::acos(-1.0);
  return 0.5 * p.width / std::tan(0.5 * p.fov_deg * pi / 180.0) * pi / 180.0;
}

TEST(StateDensity, BalancedKeepsTwentySitesPerDegreeUpToHalfASitePerPixel) {
  // 1080p at about 64 px/deg: 0.31 site/px; 720p (43 px/deg) 0.47; 4K
  // the preset's own 0.25; a 256x144 frame (9 px/deg) the cap's 0.5.
  const struct {
    cv::Size size;
    double sites_per_pixel;
  } cases[] = {{{3840, 2160}, 0.25}, {{1920, 1080}, 0.312}, {{1280, 720}, 0.468}, {{256, 144}, 0.5}};
  for (const auto& c : cases) {
    const Plan p = plan_for("balanced", c.size.width, c.size.height);
    EXPECT_NEAR(p.retina.sites_per_pixel, c.sites_per_pixel, 0.001) << c.size;
    if (p.retina.sites_per_pixel > 0.25 && p.retina.sites_per_pixel < 0.5) {  // raised, not capped
      EXPECT_NEAR(p.retina.sites_per_pixel * centre_ppd(p), 20.0, 1e-6) << c.size;
    }
  }
}

TEST(StateDensity, AWideFieldOfViewIsCappedAtHalfASitePerPixel) {
  Settings s;
  apply_quality_preset("balanced", s);
  s.geometry.fov_deg = 100.0;  // 1920 px over 100 deg: about 11 px/deg at the centre
  io::SourceInfo info;
  info.width = 1920;
  info.height = 1080;
  info.frames_per_second = 30;
  const Plan p = compile_plan(s, info);
  EXPECT_LT(centre_ppd(p), 20.0 / 0.5);
  EXPECT_EQ(p.retina.sites_per_pixel, 0.5);
}

TEST(StateDensity, NoFloorLeavesTheSitesPerPixelAndFastAndReferenceHaveNone) {
  EXPECT_EQ(plan_for("balanced", 1920, 1080, 0.0).retina.sites_per_pixel, 0.25);
  EXPECT_EQ(plan_for("fast", 256, 144).retina.sites_per_pixel, 0.25);
  EXPECT_EQ(plan_for("fast", 1920, 1080).retina.sites_per_pixel, 0.25);
  EXPECT_EQ(plan_for("reference", 1920, 1080).retina.sites_per_pixel, 1.0);
}

}  // namespace
}  // namespace eyestream::pipeline
