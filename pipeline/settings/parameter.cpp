#include "pipeline/settings/parameter.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/error.hpp"
#include "io/staged_file.hpp"

namespace eyestream::pipeline {

namespace {

std::string number_text(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

double parse_number(const Param& p, const std::string& text, const std::string& where) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v))
    throw UsageError(where + ": '" + text + "' is not a number");
  if (v < p.min || v > p.max)
    throw UsageError(where + ": " + text + " is outside its range " + number_text(p.min) + " to " + number_text(p.max) +
                     (p.unit.empty() ? "" : " " + p.unit));
  return v;
}

bool is_bool(const Param& p) { return std::holds_alternative<bool*>(p.target); }

std::string range_text(const Param& p) {
  if (!p.choices.empty()) {
    std::string s;
    for (const std::string& c : p.choices) s += (s.empty() ? "" : "|") + c;
    return s;
  }
  if (std::holds_alternative<std::string*>(p.target) || is_bool(p)) return "";
  return number_text(p.min) + " to " + number_text(p.max);
}

}  // namespace

Param number(std::string name, std::string unit, std::string help, std::string group, ParamTarget target, double min,
             double max) {
  return Param{std::move(name), std::move(unit), std::move(help), std::move(group), target, min, max, {}};
}

Param flag(std::string name, std::string help, std::string group, bool* target) {
  return Param{std::move(name), "", std::move(help), std::move(group), target, 0, 1, {}};
}

Param text(std::string name, std::string help, std::string group, std::string* target) {
  return Param{std::move(name), "", std::move(help), std::move(group), target, -1e300, 1e300, {}};
}

Param choice(std::string name, std::string help, std::string group, ParamTarget target,
             std::vector<std::string> choices) {
  return Param{std::move(name), "", std::move(help), std::move(group), target, -1e300, 1e300, std::move(choices)};
}

void ParamSet::add(Param p) { params_.push_back(std::move(p)); }

ParamSet ParamSet::subset(const std::vector<std::string>& groups) const {
  ParamSet out;
  for (const Param& p : params_)
    if (std::find(groups.begin(), groups.end(), p.group) != groups.end()) out.add(p);
  return out;
}

std::string ParamSet::value_text(const Param& p) {
  struct Visitor {
    std::string operator()(double* v) const { return number_text(*v); }
    std::string operator()(int* v) const { return std::to_string(*v); }
    std::string operator()(std::int64_t* v) const { return std::to_string(*v); }
    std::string operator()(bool* v) const { return *v ? "true" : "false"; }
    std::string operator()(std::string* v) const { return *v; }
    std::string operator()(std::optional<double>* v) const { return *v ? number_text(**v) : "unset"; }
  };
  return std::visit(Visitor{}, p.target);
}

void ParamSet::set_text(const Param& p, const std::string& text, const std::string& origin) {
  const std::string where = origin + "--" + p.name;
  if (!p.choices.empty() && std::find(p.choices.begin(), p.choices.end(), text) == p.choices.end())
    throw UsageError(where + ": '" + text + "' is not one of " + range_text(p));
  if (auto* b = std::get_if<bool*>(&p.target)) {
    if (text == "true" || text == "1" || text == "on")
      **b = true;
    else if (text == "false" || text == "0" || text == "off")
      **b = false;
    else
      throw UsageError(where + ": '" + text + "' is not true or false");
  } else if (auto* s = std::get_if<std::string*>(&p.target)) {
    **s = text;
  } else if (auto* d = std::get_if<double*>(&p.target)) {
    **d = parse_number(p, text, where);
  } else if (auto* o = std::get_if<std::optional<double>*>(&p.target)) {
    **o = parse_number(p, text, where);
  } else {
    const double v = parse_number(p, text, where);
    if (v != std::floor(v)) throw UsageError(where + ": '" + text + "' is not a whole number");
    if (auto* i = std::get_if<int*>(&p.target))
      **i = int(v);
    else
      **std::get_if<std::int64_t*>(&p.target) = std::int64_t(v);
  }
}

void ParamSet::set_json(const Param& p, const nlohmann::json& value, const std::string& origin) {
  if (value.is_string())
    set_text(p, value.get<std::string>(), origin);
  else if (value.is_boolean())
    set_text(p, value.get<bool>() ? "true" : "false", origin);
  else if (value.is_number()) {
    std::ostringstream s;
    s.precision(17);
    s << value.get<double>();
    set_text(p, s.str(), origin);
  } else {
    throw UsageError(origin + "--" + p.name + ": expected a number, string or boolean");
  }
}

void ParamSet::bind(CLI::App& app) {
  raw_.assign(params_.size(), std::string());
  flag_votes_.assign(params_.size(), 0);
  options_.clear();
  for (size_t i = 0; i < params_.size(); ++i) {
    const Param& p = params_[i];
    const std::string value = p.shown_default.empty() ? value_text(p) : p.shown_default;
    std::string help =
        p.help + (p.unit.empty() ? "" : " [" + p.unit + "]") + " (default " + (value.empty() ? "none" : value);
    const std::string range = range_text(p);
    help += range.empty() ? ")" : "; " + range + ")";
    CLI::Option* opt = nullptr;
    if (is_bool(p)) {
      opt = app.add_flag("--" + p.name + ",!--no-" + p.name, flag_votes_[i], help);
    } else {
      opt = app.add_option("--" + p.name, raw_[i], help);
      const bool text = std::holds_alternative<std::string*>(p.target);
      opt->type_name(!p.choices.empty() ? "CHOICE" : text ? "TEXT" : "NUMBER");
    }
    opt->group(p.group);
    options_.push_back(opt);
  }
}

namespace {

// Edit distance (insertions, deletions, substitutions) between two names.
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// Options a parameter file may not hold: the run's inputs and outputs.
const char* const kCommandLineOnly[] = {"input", "gaze", "output", "config"};

// " (did you mean 'x'?)" for the parameter nearest to `key` (underscores
// read as dashes), when it is within a third of the key's length; "".
std::string suggestion(const std::string& key, const std::vector<Param>& params) {
  std::string dashed = key;
  std::replace(dashed.begin(), dashed.end(), '_', '-');
  const Param* best = nullptr;
  size_t best_distance = std::max<size_t>(2, dashed.size() / 3) + 1;
  for (const Param& p : params) {
    const size_t d = edit_distance(dashed, p.name);
    if (d < best_distance) best = &p, best_distance = d;
  }
  return best ? " (did you mean '" + best->name + "'?)" : "";
}

}  // namespace

void ParamSet::apply_json(const nlohmann::json& object, const std::string& origin) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    auto found = std::find_if(params_.begin(), params_.end(), [&](const Param& p) { return p.name == it.key(); });
    // The run's inputs and outputs are named on its command line, not in a
    // file of settings shared by runs.
    std::string lower = it.key();
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const char* name : kCommandLineOnly)
      if (found == params_.end() && edit_distance(lower, name) <= (lower.size() >= 3 ? 1u : 0u))
        throw UsageError(origin + ": '" + it.key() + "' is the run's --" + name +
                         ", which goes on the command line, not in a parameter file");
    if (found == params_.end())
      throw UsageError(origin + ": unknown parameter '" + it.key() + "'" + suggestion(it.key(), params_));
    set_json(*found, it.value(), origin + ": ");
  }
}

nlohmann::json read_parameter_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the parameter file");
  io::protect_input(path);
  nlohmann::json object;
  try {
    in >> object;
  } catch (const std::exception& e) {
    throw InputError(path + ": not valid JSON: " + e.what());
  }
  if (!object.is_object()) throw InputError(path + ": expected a JSON object of parameter names");
  return object;
}

void ParamSet::apply(const std::string& config_path) {
  if (!config_path.empty()) apply_json(read_parameter_file(config_path), config_path);
  for (size_t i = 0; i < params_.size(); ++i)
    if (options_.at(i)->count() > 0)
      set_text(params_[i], is_bool(params_[i]) ? (flag_votes_[i] > 0 ? "true" : "false") : raw_[i], "");
}

}  // namespace eyestream::pipeline
