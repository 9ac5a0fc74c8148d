// For fuzz targets whose reader takes a path: the input written to one
// scratch file per process (the name keeps the extension the reader
// dispatches on).
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

namespace eyestream::fuzz {

inline std::string write_input(const std::uint8_t* data, std::size_t size, const std::string& extension) {
  const std::string path = "/tmp/eyestream-fuzz-" + std::to_string(::getpid()) + extension;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

}  // namespace eyestream::fuzz
