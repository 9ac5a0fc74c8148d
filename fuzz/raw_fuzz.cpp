// libFuzzer target: raw float frames on standard input. The first two bytes
// give the frame's width and height (1 to 16); the rest is the stream.
#include <cstddef>
#include <cstdint>
#include <cstdio>

#include "io/error.hpp"
#include "io/raw_stream_source.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  eyestream::io::RawStreamOptions o;
  o.width = 1 + data[0] % 16;
  o.height = 1 + data[1] % 16;
  std::FILE* stream = fmemopen(const_cast<std::uint8_t*>(data + 2), size - 2, "rb");
  if (!stream) return 0;
  try {
    eyestream::io::RawStreamSource source(stream, "fuzz", o);
    while (source.next()) {
    }
  } catch (const eyestream::InputError&) {
  }
  std::fclose(stream);
  return 0;
}
