// The CIE General Disability Glare equation (CIE 146:2002, from Vos and van
// den Berg): the veiling luminance a point source of
// illuminance E at the eye lays at angle t from it,
//   L_veil / E = 10/t^3 + (5/t^2 + 0.1 p/t) (1 + (A/62.5)^4) + 0.0025 p
// per steradian, t in degrees, valid from 0.1 to 100 deg, for age A and
// ocular pigmentation p. The formula here is checked against its published
// restatements (Vos, Clin. Exp. Optom. 86:363, 2003, as
// quoted); the CIE report's own text was not available to check it against.
#pragma once

namespace eyestream::glare {

// The equation as published (t_deg > 0; no clamping).
double cie_general_glare(double t_deg, double age_years, double pigmentation);

// The scattered part as a PSF component: the equation from 0.1 deg out,
// constant at its 0.1 deg value inside that (where the CIE gives nothing),
// scaled to unit volume over the hemisphere; scattered_share is that
// volume before scaling (the share of the light the equation scatters).
struct CieScatter {
  double age_years = 25.0, pigmentation = 0.5;
  double scattered_share = 0.0;
  double density(double t_deg) const;  // per steradian, unit volume
};
CieScatter cie_scatter(double age_years, double pigmentation);

}  // namespace eyestream::glare
