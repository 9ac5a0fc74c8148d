// libFuzzer target: the video reader (libavformat and libavcodec behind
// it), decoding up to eight frames. Malformed files end in InputError.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_file.hpp"
#include "io/error.hpp"
#include "io/library_logging.hpp"
#include "io/video_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  eyestream::io::set_library_verbosity(false);
  try {
    eyestream::io::VideoReader reader(eyestream::fuzz::write_input(data, size, ".mp4"));
    if (std::int64_t(reader.width()) * reader.height() > 1'000'000) return 0;
    for (int i = 0; i < 8 && reader.next(); ++i) {
    }
  } catch (const eyestream::InputError&) {
  }
  return 0;
}
