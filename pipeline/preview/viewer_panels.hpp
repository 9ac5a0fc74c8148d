// The panels of a preview: one per viewer of `--viewers`, after a plain
// tone-curve panel of the input with `--side-by-side`; one panel (the
// configured viewer) otherwise.
#pragma once

#include <string>
#include <vector>

#include "pipeline/settings/settings.hpp"

namespace eyestream::pipeline {

struct PanelSpec {
  std::string label;  // burned in above the panel
  Settings settings;  // the run's settings with this viewer's applied
  bool viewer = true;  // false for the plain tone-curve panel (it has no report rows)
};

// `--viewers` entries are ages in years ("70") or JSON files holding viewer
// parameters (any of the optics, retina, afterimage and mesopic groups of
// `eyestream run --help`) and an optional "label". UsageError naming the
// entry or file for anything else.
std::vector<PanelSpec> panel_specs(const Settings& s);

}  // namespace eyestream::pipeline
