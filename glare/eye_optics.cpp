#include "glare/eye_optics.hpp"

#include <algorithm>

#include "glare/pupil.hpp"
#include "glare/vos_psf.hpp"

namespace eyestream::glare {

EyeOptics::EyeOptics(const ViewerProfile& viewer, PsfModel model, bool flare, double frame_area_deg2,
                     double frame_ppd)
    : viewer_(viewer), model_(model), flare_(flare), frame_area_deg2_(frame_area_deg2), frame_ppd_(frame_ppd) {
  if (model_ == PsfModel::cie) cie_ = cie_scatter(viewer.age_years, viewer.pigmentation);
}

double EyeOptics::pupil_mm(double a) const { return glare::pupil_mm(viewer_, a, frame_area_deg2_); }

PsfWeights EyeOptics::weights(double a) const { return weights(a, pupil_mm(a)); }

PsfWeights EyeOptics::weights(double a, double pupil) const {
  const PsfWeights vos = psf_weights(viewer_, a, pupil);
  if (model_ == PsfModel::vos) return vos;
  // The CIE equation fixes the scattered share for the viewer; the halo
  // follows adaptation and pupil as in the Vos model; haze adds bloom; the
  // core keeps the rest.
  PsfWeights w;
  w.inner = cie_.scattered_share;
  w.halo = vos.halo;
  const double core = 1.0 - w.inner - w.halo;
  w.outer = std::clamp(viewer_.haze, 0.0, 1.0) * core;  // haze's share of the core
  w.core = core - w.outer;
  return w;
}

std::function<double(double)> EyeOptics::component(int slot) const {
  switch (slot) {
    case 0:
      return vos_f0;
    case 1:
      if (model_ == PsfModel::cie) return [s = cie_](double t) { return s.density(t); };
      return vos_f1;
    default:
      return vos_f2;
  }
}

}  // namespace eyestream::glare
