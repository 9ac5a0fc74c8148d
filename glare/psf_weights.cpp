#include "glare/psf_weights.hpp"

#include <algorithm>
#include <cmath>

namespace eyestream::glare {

namespace {

constexpr PsfWeights kPhotopic{0.384, 0.478, 0.138, 0.0};    // Spencer et al. 1995 eq. 9
constexpr PsfWeights kMesopic{0.368, 0.478, 0.138, 0.016};   // Spencer et al. 1995 eq. 9
constexpr PsfWeights kScotopic{0.282, 0.478, 0.207, 0.033};  // Spencer et al. 1995 eq. 9

PsfWeights mix(const PsfWeights& a, const PsfWeights& b, double f) {
  return {a.core + f * (b.core - a.core), a.inner + f * (b.inner - a.inner), a.outer + f * (b.outer - a.outer),
          a.halo + f * (b.halo - a.halo)};
}

}  // namespace

PsfWeights psf_weights(const ViewerProfile& viewer, double a, double pupil_mm) {
  const double scotopic = -2.0, photopic = std::log10(3.0), middle = 0.5 * (scotopic + photopic);
  PsfWeights w = a <= scotopic  ? kScotopic
                 : a <= middle  ? mix(kScotopic, kMesopic, (a - scotopic) / (middle - scotopic))
                 : a < photopic ? mix(kMesopic, kPhotopic, (a - middle) / (photopic - middle))
                                : kPhotopic;
  // The halo needs a pupil wider than about 3 mm; what it loses goes back to the core.
  const double f = std::clamp((pupil_mm - 2.5) / 1.0, 0.0, 1.0);
  const double halo = w.halo * f * f * (3.0 - 2.0 * f);
  w.core += w.halo - halo;
  w.halo = halo;
  // Age (Spencer et al. 1995 eq. 10) moves 6.9e-9 A^4 from f0 to f2. At great ages
  // that would take more than the core has: the move stops at 90 % of the
  // core (reached near 85 years with photopic weights, 78 with scotopic),
  // so the weights stay valid and nothing is renormalised away from the
  // corona at any age.
  const double aging = std::min(6.9e-9 * std::pow(viewer.age_years, 4.0), 0.9 * w.core);
  w.core -= aging;
  w.outer += aging;
  // Haze: the viewer's haze share of what is left of the core goes to the bloom.
  const double hazed = std::clamp(viewer.haze, 0.0, 1.0) * w.core;
  w.core -= hazed;
  w.outer += hazed;
  return w;
}

}  // namespace eyestream::glare
