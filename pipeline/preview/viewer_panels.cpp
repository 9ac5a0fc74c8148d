#include "pipeline/preview/viewer_panels.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/error.hpp"
#include "pipeline/settings/parameter.hpp"

namespace eyestream::pipeline {

namespace {

std::string age_label(double age) {
  std::ostringstream o;
  o << "age " << age;
  return o.str();
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    const size_t a = item.find_first_not_of(" \t"), b = item.find_last_not_of(" \t");
    if (a == std::string::npos) throw UsageError("--viewers '" + text + "': an empty entry");
    items.push_back(item.substr(a, b - a + 1));
  }
  if (items.empty()) throw UsageError("--viewers: no viewer given");
  return items;
}

PanelSpec viewer_from_file(const Settings& base, const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw UsageError("--viewers: no viewer file '" + path + "'");
  nlohmann::json object = read_parameter_file(path);
  PanelSpec p{std::filesystem::path(path).stem().string(), base, true};
  if (object.contains("label")) {
    if (!object["label"].is_string()) throw InputError(path + ": \"label\" must be a string");
    p.label = object["label"].get<std::string>();
    object.erase("label");
  }
  run_parameters(p.settings)
      .subset({"Glare (the viewer's optics)", "Retina", "Afterimages (retina state)", "Mesopic vision"})
      .apply_json(object, path);
  return p;
}

PanelSpec viewer_entry(const Settings& base, const std::string& entry) {
  char* end = nullptr;
  const double age = std::strtod(entry.c_str(), &end);
  if (end == entry.c_str() + entry.size()) {
    if (!(age >= 1 && age <= 100)) throw UsageError("--viewers: age '" + entry + "' is outside 1-100 years");
    PanelSpec p{age_label(age), base, true};
    p.settings.viewer.age_years = age;
    return p;
  }
  return viewer_from_file(base, entry);
}

}  // namespace

std::vector<PanelSpec> panel_specs(const Settings& s) {
  std::vector<PanelSpec> panels;
  if (s.side_by_side) {
    PanelSpec plain{"input, tone curve only", s, false};
    plain.settings.glare = false;
    plain.settings.mesopic = false;
    plain.settings.bleaching_afterimages = false;
    plain.settings.adaptation_afterimages = false;
    plain.settings.lens_yellowing = false;  // the input as it is
    panels.push_back(plain);
  }
  if (s.viewers.empty())
    panels.push_back({age_label(s.viewer.age_years), s, true});
  else
    for (const std::string& entry : split_list(s.viewers)) panels.push_back(viewer_entry(s, entry));
  return panels;
}

}  // namespace eyestream::pipeline
