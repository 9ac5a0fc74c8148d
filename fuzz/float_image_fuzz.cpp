// libFuzzer target: the Radiance .hdr, PFM and TIFF readers. The first byte
// picks the format; the rest is the file. Malformed files end in InputError or
// UsageError.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_file.hpp"
#include "io/error.hpp"
#include "io/float_image_source.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  eyestream::io::ExrSequenceOptions o;
  o.max_pixels = 1'000'000;
  try {
    eyestream::io::FloatImageSource source(
        eyestream::fuzz::write_input(data + 1, size - 1, data[0] % 3 == 0 ? ".hdr" : data[0] % 3 == 1 ? ".pfm" : ".tif"),
        o);
    while (source.next()) {
    }
  } catch (const eyestream::InputError&) {
  } catch (const eyestream::UsageError&) {
  }
  return 0;
}
