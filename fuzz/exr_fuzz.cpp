// libFuzzer target: the EXR reader. Malformed files end in InputError,
// never in a crash, a hang or an allocation the guard would refuse.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_file.hpp"
#include "io/error.hpp"
#include "io/exr_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    eyestream::io::read_exr(eyestream::fuzz::write_input(data, size, ".exr"), 1'000'000);
  } catch (const eyestream::InputError&) {
  }
  return 0;
}
