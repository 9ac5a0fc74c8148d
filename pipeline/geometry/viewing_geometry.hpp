// Visual degrees per pixel from the viewing condition (docs/model.md).
#pragma once

#include <string>

namespace eyestream::pipeline {

struct ViewingGeometry {
  double fov_deg = 0.0;             // horizontal field of view of the frame; 0: derive from the display
  double display_diagonal_m = 0.6;  // the frame fills the display (Jacobs et al. 2015's condition)
  double viewing_distance_m = 1.0;
  // How the frame maps to directions (frame_projection.hpp): rectilinear
  // (renderers, simulators, a flat display) or equidistant.
  std::string projection = "rectilinear";
};

// Horizontal field of view (deg) of a width x height frame: fov_deg when
// set, else 2 atan(w / 2d) with w the display width for the frame's aspect.
double field_of_view_deg(const ViewingGeometry& g, int width, int height);

// Pixels per visual degree at the frame's centre (about 61 for a 1920-px
// rectilinear frame under the default condition; width / fov when
// equidistant).
double pixels_per_degree(const ViewingGeometry& g, int width, int height);

}  // namespace eyestream::pipeline
