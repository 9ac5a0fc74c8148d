#include "pipeline/geometry/viewing_geometry.hpp"

#include <cmath>

namespace eyestream::pipeline {

double field_of_view_deg(const ViewingGeometry& g, int width, int height) {
  if (g.fov_deg > 0) return g.fov_deg;
  const double w = double(width), h = double(height);
  const double display_width_m = g.display_diagonal_m * w / std::hypot(w, h);
  return 2.0 * std::atan(display_width_m / (2.0 * g.viewing_distance_m)) * 180.0 / M_PI;
}

double pixels_per_degree(const ViewingGeometry& g, int width, int height) {
  const double fov = field_of_view_deg(g, width, height);
  if (g.projection == "equidistant") return double(width) / fov;
  return 0.5 * double(width) / std::tan(0.5 * fov * M_PI / 180.0) * M_PI / 180.0;
}

}  // namespace eyestream::pipeline
