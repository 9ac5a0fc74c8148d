// libFuzzer target: the JSON config reader applied to every run parameter.
// Bad values must be InputError or UsageError naming the parameter.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "io/error.hpp"
#include "pipeline/settings/parameter.hpp"
#include "pipeline/settings/settings.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const nlohmann::json config = nlohmann::json::parse(data, data + size, nullptr, false);
  if (config.is_discarded() || !config.is_object()) return 0;
  eyestream::pipeline::Settings settings;
  try {
    eyestream::pipeline::run_parameters(settings).apply_json(config, "fuzz.json");
  } catch (const eyestream::InputError&) {
  } catch (const eyestream::UsageError&) {
  }
  return 0;
}
