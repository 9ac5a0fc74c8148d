// One declaration per parameter (name, unit, default, range, help), in the
// manner of libavfilter's option tables: the command line, the JSON config
// file, --help and range checking all come from it.
#pragma once

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace eyestream::pipeline {

// Where a parameter's value lives. The default is the value found there
// when the table is built (module structs carry their defaults next to the
// model they belong to, with the source cited).
using ParamTarget = std::variant<double*, int*, std::int64_t*, bool*, std::string*, std::optional<double>*>;

struct Param {
  std::string name;   // command-line --name and config key
  std::string unit;   // e.g. "cd/m^2", "deg", "log10/s"; empty if none
  std::string help;   // one line
  std::string group;  // heading in --help
  ParamTarget target;
  double min = -1e300, max = 1e300;  // inclusive range for numbers
  std::vector<std::string> choices;  // allowed values for strings
  std::string shown_default;         // what --help says the default is, when it depends on the machine
};

// Declarations by kind.
Param number(std::string name, std::string unit, std::string help, std::string group, ParamTarget target, double min,
             double max);
Param flag(std::string name, std::string help, std::string group, bool* target);
Param text(std::string name, std::string help, std::string group, std::string* target);
Param choice(std::string name, std::string help, std::string group, ParamTarget target,
             std::vector<std::string> choices);

class ParamSet {
 public:
  void add(Param p);
  // The parameters of the named groups only (for commands that need a few).
  ParamSet subset(const std::vector<std::string>& groups) const;
  const std::vector<Param>& params() const { return params_; }

  // Registers every parameter as an option of `app`. Help text shows the
  // unit, the default, and the range or choices.
  void bind(CLI::App& app);
  // After app.parse(): applies the config file (if any), then the values
  // given on the command line, which win. Validates each against its
  // declaration; UsageError naming the parameter (and file) otherwise.
  void apply(const std::string& config_path);

  // Sets each parameter named by a key of the JSON object; UsageError
  // naming `origin` for an unknown name or a bad value.
  void apply_json(const nlohmann::json& object, const std::string& origin);

  // Sets one parameter from text or JSON; `origin` prefixes messages.
  static void set_text(const Param& p, const std::string& text, const std::string& origin);
  static void set_json(const Param& p, const nlohmann::json& value, const std::string& origin);
  // The current value as text (defaults in help, plans, reports).
  static std::string value_text(const Param& p);

 private:
  std::vector<Param> params_;
  std::vector<std::string> raw_;
  std::vector<int> flag_votes_;  // flags: +1 per --x, -1 per --no-x; the last word wins by sign
  std::vector<CLI::Option*> options_;
};

// Reads a JSON object of parameter values (a config or viewer file) and
// protects it from being overwritten; InputError naming the file.
nlohmann::json read_parameter_file(const std::string& path);

}  // namespace eyestream::pipeline
