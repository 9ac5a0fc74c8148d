#include "pipeline/viewing_geometry.hpp"

#include <gtest/gtest.h>

namespace eyestream::pipeline {
namespace {

// MODEL.md 0: the default condition (0.6 m 16:9 display at 1 m) is about
// 29 deg wide, about 64 px/deg for a 1920-px frame.
TEST(ViewingGeometry, DefaultConditionMatchesTheModel) {
  const ViewingGeometry g;
  EXPECT_NEAR(field_of_view_deg(g, 1920, 1080), 29.3, 0.1);
  EXPECT_NEAR(pixels_per_degree(g, 1920, 1080), 65.5, 0.5);
}

TEST(ViewingGeometry, ExplicitFieldOfViewWins) {
  ViewingGeometry g;
  g.fov_deg = 90.0;
  EXPECT_DOUBLE_EQ(pixels_per_degree(g, 1800, 1000), 20.0);
}

TEST(ViewingGeometry, CloserViewingWidensTheField) {
  ViewingGeometry near, far;
  near.viewing_distance_m = 0.5;
  EXPECT_GT(field_of_view_deg(near, 640, 360), field_of_view_deg(far, 640, 360));
}

}  // namespace
}  // namespace eyestream::pipeline
