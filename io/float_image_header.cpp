#include "io/float_image_header.hpp"

#include <fstream>

#include "io/error.hpp"
#include "io/frame_sequence.hpp"
#include "io/pfm_file.hpp"
#include "io/radiance_hdr.hpp"

namespace eyestream::io {

namespace {

[[noreturn]] void malformed(const std::string& path, const std::string& what) {
  throw InputError(path + ": " + what);
}

cv::Size checked(const std::string& path, long long w, long long h) {
  if (w <= 0 || h <= 0 || w > 1000000 || h > 1000000)
    malformed(path, "declares a size of " + std::to_string(w) + "x" + std::to_string(h));
  return {int(w), int(h)};
}

// TIFF: byte order ("II" or "MM"), 42, the first directory's offset; its
// ImageWidth (256) and ImageLength (257) entries, SHORT or LONG.
cv::Size tiff_size(std::istream& in, const std::string& path) {
  unsigned char head[8];
  if (!in.read(reinterpret_cast<char*>(head), 8)) malformed(path, "not a TIFF file");
  const bool little = head[0] == 'I' && head[1] == 'I';
  if (!little && !(head[0] == 'M' && head[1] == 'M')) malformed(path, "not a TIFF file");
  const auto number = [&](const unsigned char* b, int bytes) {
    unsigned long long v = 0;
    for (int i = 0; i < bytes; ++i) v |= (unsigned long long)b[little ? i : bytes - 1 - i] << (8 * i);
    return v;
  };
  if (number(head + 2, 2) == 43) malformed(path, "BigTIFF is not read; save as a classic TIFF");
  if (number(head + 2, 2) != 42) malformed(path, "not a TIFF file");
  in.seekg(std::streamoff(number(head + 4, 4)));
  unsigned char count_bytes[2];
  if (!in.read(reinterpret_cast<char*>(count_bytes), 2)) malformed(path, "not a TIFF file (no image directory)");
  long long w = 0, h = 0;
  for (unsigned long long i = 0, n = number(count_bytes, 2); i < n && i < 4096; ++i) {
    unsigned char e[12];
    if (!in.read(reinterpret_cast<char*>(e), 12)) malformed(path, "not a TIFF file (truncated image directory)");
    const unsigned long long tag = number(e, 2), type = number(e + 2, 2);
    const long long value = type == 3 ? (long long)number(e + 8, 2) : type == 4 ? (long long)number(e + 8, 4) : -1;
    if (tag == 256) w = value;
    if (tag == 257) h = value;
  }
  return checked(path, w, h);
}

}  // namespace

cv::Size float_image_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) malformed(path, "cannot open");
  const std::string ext = lower_extension(path);
  if (ext == ".tif" || ext == ".tiff") return tiff_size(in, path);
  return ext == ".pfm" ? pfm_size(path) : radiance_hdr_size(path);  // their readers' own header checks
}

}  // namespace eyestream::io
