// eyestream::psf (eyestream/eye.hpp): the viewer's point-spread function
// as `eyestream psf` computes it.
#include <cmath>

#include "eyestream/eye.hpp"
#include "pipeline/api/api_settings.hpp"
#include "pipeline/tools/psf_command.hpp"

namespace eyestream {

Psf psf(int width, int height, double adaptation_cd_m2, const std::map<std::string, std::string>& settings) {
  return translated([&] {
    if (width < 1 || height < 1 || !(adaptation_cd_m2 > 0.0) || !std::isfinite(adaptation_cd_m2))
      throw UsageError("psf: needs a positive frame size and adaptation luminance, not " + std::to_string(width) +
                       "x" + std::to_string(height) + " at " + std::to_string(adaptation_cd_m2) + " cd/m^2");
    const pipeline::ViewerPsf v =
        pipeline::viewer_psf(compile_settings(settings), width, height, std::log10(adaptation_cd_m2));
    Psf out;
    out.kernel = v.kernel;
    out.pixels_per_degree = v.pixels_per_degree;
    out.pupil_mm = v.summary.pupil_mm;
    return out;
  });
}

}  // namespace eyestream
