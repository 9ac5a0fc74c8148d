// The eye's point-spread function components of Vos (f0, f1, f2) and the
// Hemenger lenticular halo (f3), Spencer et al. 1995 eqs. 5-9. Each is a
// density over the hemisphere (per steradian) of the angle t in degrees from
// the source, with unit volume.
#pragma once

#include <functional>

namespace eyestream::glare {

double vos_f0(double t_deg);                        // unscattered core
double vos_f1(double t_deg);                        // dominant below 1-2 deg
double vos_f2(double t_deg);                        // dominant beyond 1 deg
double vos_f3(double t_deg, double wavelength_nm);  // lenticular halo ring

// 2 pi * integral over u in [0, pi/2] of f(t_deg(u)) sin(u) du, u in
// radians: the volume of a radially symmetric density over the hemisphere
// (docs/model.md). Quadrature dense near t = 0, where the core is narrow.
double hemisphere_integral(const std::function<double(double t_deg)>& f, int samples = 200000);

}  // namespace eyestream::glare
