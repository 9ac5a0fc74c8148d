#include "pipeline/geometry/viewing_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace eyestream::pipeline {
namespace {

// docs/model.md: the default condition (0.6 m 16:9 display at 1 m) is about
// 29 deg wide. The display is a rectilinear view: at its centre a 1920-px
// frame has f = 960 / tan(14.65 deg) px per radian, 64.1 px/deg; across the
// whole width it averages 1920 / 29.3 = 65.5.
TEST(ViewingGeometry, DefaultConditionMatchesTheModel) {
  ViewingGeometry g;
  EXPECT_NEAR(field_of_view_deg(g, 1920, 1080), 29.3, 0.1);
  EXPECT_NEAR(pixels_per_degree(g, 1920, 1080), 64.1, 0.05);
  g.projection = "equidistant";
  EXPECT_NEAR(pixels_per_degree(g, 1920, 1080), 65.5, 0.05);
}

TEST(ViewingGeometry, ExplicitFieldOfViewWins) {
  ViewingGeometry g;
  g.fov_deg = 90.0;
  EXPECT_NEAR(pixels_per_degree(g, 1800, 1000), 900.0 * M_PI / 180.0, 1e-9) << "f = 900 px at 90 deg";
  g.projection = "equidistant";
  EXPECT_DOUBLE_EQ(pixels_per_degree(g, 1800, 1000), 20.0);
}

TEST(ViewingGeometry, CloserViewingWidensTheField) {
  ViewingGeometry near, far;
  near.viewing_distance_m = 0.5;
  EXPECT_GT(field_of_view_deg(near, 640, 360), field_of_view_deg(far, 640, 360));
}

}  // namespace
}  // namespace eyestream::pipeline
