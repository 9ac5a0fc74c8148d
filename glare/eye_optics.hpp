// The viewer's optics as the glare stage uses them: which PSF model, the
// shapes of its components, their weights at an adaptation level, and the
// pupil (docs/model.md). One object built per sequence; the kernels
// (psf_kernel.hpp) are built from it once, and each frame only re-weights.
#pragma once

#include <functional>

#include "glare/cie_glare.hpp"
#include "glare/psf_weights.hpp"
#include "glare/viewer.hpp"

namespace eyestream::glare {

enum class PsfModel {
  vos,  // Spencer et al. 1995: f0..f3, blended by adaptation, age term of eq. 10
  cie   // CIE 146:2002 general equation for the scattered part; Vos's core and halo
};

class EyeOptics {
 public:
  // frame_area_deg2: the frame's angular area, the pupil's adapting field
  // when the viewer names none. flare: multiply flare lines into the PSF.
  // frame_pixels_per_degree: the frame's resolution, which sets the flare
  // lines' least width in every kernel (0: each kernel's own).
  explicit EyeOptics(const ViewerProfile& viewer = {}, PsfModel model = PsfModel::vos, bool flare = false,
                     double frame_area_deg2 = 0.0, double frame_pixels_per_degree = 0.0);

  const ViewerProfile& viewer() const { return viewer_; }
  PsfModel model() const { return model_; }
  bool flare_lines() const { return flare_; }
  double frame_pixels_per_degree() const { return frame_ppd_; }

  double pupil_mm(double adaptation_log) const;

  // The component weights at adaptation 10^adaptation_log cd/m^2, for the
  // viewer's pupil there. They sum to 1.
  PsfWeights weights(double adaptation_log) const;
  // The same for a pupil of pupil_mm (the pupil has its own dynamics).
  PsfWeights weights(double adaptation_log, double pupil_mm) const;

  // The components' radial densities (per steradian, unit volume, t in
  // degrees) for the core, inner and outer slots: Vos f0, f1, f2; for cie,
  // f0, the CIE scattered part (cie_glare.hpp) and f2 (haze only). The halo
  // slot is always Vos f3.
  std::function<double(double)> component(int slot) const;

 private:
  ViewerProfile viewer_;
  PsfModel model_;
  bool flare_;
  double frame_area_deg2_, frame_ppd_;
  CieScatter cie_;
};

}  // namespace eyestream::glare
