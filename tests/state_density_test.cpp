// The retina state's grid is never coarser than --state-least-density
// sites per degree (balanced: 20), up to one site per pixel, whatever the
// frame size (pipeline/settings/plan.cpp). The pixels per degree are
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

TEST(StateDensity, BalancedKeepsTwentySitesPerDegreeAtEverySize) {
  for (const cv::Size size : {cv::Size(3840, 2160), cv::Size(1920, 1080), cv::Size(1280, 720), cv::Size(256, 144)}) {
    const Plan p = plan_for("balanced", size.width, size.height);
    const double ppd = centre_ppd(p);
    const double want = std::min(std::max(0.25, 20.0 / ppd), 1.0);
    EXPECT_NEAR(p.retina.sites_per_pixel, want, 1e-9) << size;
    EXPECT_TRUE(p.retina.sites_per_pixel * ppd >= 20.0 - 1e-9 || p.retina.sites_per_pixel == 1.0) << size;
  }
  // 1080p at about 64 px/deg: 0.31 site/px; 4K: the preset's own 0.25.
  EXPECT_NEAR(plan_for("balanced", 1920, 1080).retina.sites_per_pixel, 0.31, 0.01);
  EXPECT_EQ(plan_for("balanced", 3840, 2160).retina.sites_per_pixel, 0.25);
  EXPECT_EQ(plan_for("balanced", 256, 144).retina.sites_per_pixel, 1.0);
}

TEST(StateDensity, NoFloorLeavesTheSitesPerPixelAndFastAndReferenceHaveNone) {
  EXPECT_EQ(plan_for("balanced", 1920, 1080, 0.0).retina.sites_per_pixel, 0.25);
  EXPECT_EQ(plan_for("fast", 256, 144).retina.sites_per_pixel, 0.25);
  EXPECT_EQ(plan_for("fast", 1920, 1080).retina.sites_per_pixel, 0.25);
  EXPECT_EQ(plan_for("reference", 256, 144).retina.sites_per_pixel, 1.0);
}

}  // namespace
}  // namespace eyestream::pipeline
