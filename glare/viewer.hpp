// The viewer: who is looking, in one place (docs/model.md). Everything the
// eye's optics depend on that is not the scene: age, eye pigmentation,
// glasses, haze, how the pupil is modelled, and the seed of the flare-line
// pattern of this viewer's lens.
#pragma once

#include <cstdint>

namespace eyestream::glare {

enum class PupilModel {
  moon_spencer,   // Spencer et al. 1995: luminance only
  watson_yellott  // Watson and Yellott 2012: luminance, field area and age
};

struct ViewerProfile {
  double age_years = 25.0;
  // Ocular pigmentation p of CIE 146:2002 (0 very dark eyes, 0.5 brown,
  // 1 light Caucasian, 1.2 very light blue): light through the eye wall.
  // Only the cie PSF model has a term for it.
  double pigmentation = 0.5;
  bool glasses = false;  // (myopic) glasses: more and longer flare lines (Matsuda and Ikedo)
  // Share of the unscattered core moved into the wide 1/t^2 bloom (f2) by
  // haze or fog between the light and the eye, 0..0.5 (Matsuda and Ikedo).
  double haze = 0.0;
  PupilModel pupil = PupilModel::moon_spencer;
  double pupil_field_deg = 0.0;  // Watson-Yellott: adapting field diameter; 0: the frame's own field
  std::int64_t seed = 1;         // the flare-line pattern (fixed for this viewer)
  // The upper eyelid's margin above the pupil's centre (MRD1; about 4-5 mm
  // open, 1-2 mm squinting); 0: no lid. Wave-optics lines only.
  double eyelid_mrd1_mm = 0.0;
};

}  // namespace eyestream::glare
