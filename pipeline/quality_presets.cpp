#include "pipeline/quality_presets.hpp"

#include "io/error.hpp"

namespace eyestream::pipeline {

void apply_quality_preset(const std::string& name, Settings& s) {
  if (name == "reference") {
    s.precision = "double";
    s.state_sites_per_pixel = 1.0;
    s.substep_tolerance_deg = 0.0;
    s.psf_model = "vos";
  } else if (name == "balanced") {
    s.precision = "float";
    s.state_sites_per_pixel = 0.5;
    s.substep_tolerance_deg = 0.05;
    s.psf_model = "vos";
  } else if (name == "fast") {
    s.precision = "float";
    s.state_sites_per_pixel = 0.25;
    s.substep_tolerance_deg = 0.25;
    s.psf_model = "gaussian";
  } else {
    throw UsageError("--quality: '" + name + "' is not one of reference|balanced|fast");
  }
}

}  // namespace eyestream::pipeline
