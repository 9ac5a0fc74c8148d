// libFuzzer target: the report CSV reader behind `eyestream report`.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/error.hpp"
#include "pipeline/report/report_charts.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    eyestream::pipeline::parse_report(std::string(reinterpret_cast<const char*>(data), size), "fuzz.csv");
  } catch (const eyestream::InputError&) {
  }
  return 0;
}
