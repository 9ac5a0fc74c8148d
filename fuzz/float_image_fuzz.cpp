// libFuzzer target: the picture readers. The first byte picks the format
// (the Radiance .hdr, PFM and TIFF stills, and PNG and code TIFF, as read
// for target masks and compared frames); the rest is the file. Malformed
// files end in InputError or UsageError.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_file.hpp"
#include "io/error.hpp"
#include "io/float_image_source.hpp"
#include "io/float_tiff.hpp"
#include "io/png_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  eyestream::io::ExrSequenceOptions o;
  o.max_pixels = 1'000'000;
  static const char* const kExtensions[5] = {".hdr", ".pfm", ".tif", ".png", ".tif"};
  try {
    const int kind = data[0] % 5;
    const auto path = eyestream::fuzz::write_input(data + 1, size - 1, kExtensions[kind]);
    if (kind == 3) {
      eyestream::io::read_png(path, o.max_pixels);
      return 0;
    }
    if (kind == 4) {
      eyestream::io::read_code_tiff(path, o.max_pixels);
      return 0;
    }
    eyestream::io::FloatImageSource source(path, o);
    while (source.next()) {
    }
  } catch (const eyestream::InputError&) {
  } catch (const eyestream::UsageError&) {
  }
  return 0;
}
