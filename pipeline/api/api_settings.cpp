#include "api_settings.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "pipeline/settings/parameter.hpp"
#include "pipeline/settings/quality_presets.hpp"

namespace eyestream {

pipeline::Settings compile_settings(const std::map<std::string, std::string>& given) {
  pipeline::Settings s;
  std::map<std::string, std::string> named;
  for (const auto& [key, value] : given) {
    std::string name = key;
    std::replace(name.begin(), name.end(), '_', '-');
    named[name] = value;
  }
  if (named.count("quality")) s.quality = named["quality"];
  // "report": the frame's veil and TI (the command line asks with
  // --report FILE; here nothing is written).
  bool report = false;
  if (named.count("report")) {
    const std::string v = named["report"];
    if (v != "true" && v != "false") throw UsageError("eyestream::Eye settings: report is true or false, not '" + v + "'");
    report = v == "true";
    named.erase("report");
  }
  pipeline::apply_quality_preset(s.quality, s);
  pipeline::ParamSet params = pipeline::run_parameters(s);
  nlohmann::json object = nlohmann::json::object();
  for (const auto& [name, value] : named) object[name] = value;
  params.apply_json(object, "eyestream::Eye settings");
  if (report) s.report = "(eyestream::Eye)";  // any name: the plan only asks whether there is one
  return s;
}

}  // namespace eyestream
