#include "io/float_image_header.hpp"

#include <fstream>
#include <sstream>

#include "io/error.hpp"
#include "io/frame_sequence.hpp"

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

// PFM: "PF" or "Pf", then width and height, then the scale.
cv::Size pfm_size(std::istream& in, const std::string& path) {
  std::string magic;
  long long w = 0, h = 0;
  if (!(in >> magic) || (magic != "PF" && magic != "Pf") || !(in >> w >> h)) malformed(path, "not a PFM file");
  return checked(path, w, h);
}

// Radiance: "#?..." header lines up to an empty line, then "-Y h +X w" (or
// another order of the two axes and signs).
cv::Size hdr_size(std::istream& in, const std::string& path) {
  std::string line;
  if (!std::getline(in, line) || line.rfind("#?", 0) != 0) malformed(path, "not a Radiance .hdr file");
  for (int n = 0; std::getline(in, line) && !line.empty(); ++n)
    if (n > 1000) malformed(path, "not a Radiance .hdr file (no end of header)");
  if (!std::getline(in, line)) malformed(path, "not a Radiance .hdr file (no resolution line)");
  std::istringstream res(line);
  std::string a1, a2;
  long long n1 = 0, n2 = 0;
  if (!(res >> a1 >> n1 >> a2 >> n2) || a1.size() != 2 || a2.size() != 2)
    malformed(path, "not a Radiance .hdr file (resolution line '" + line.substr(0, 40) + "')");
  const bool y_first = a1[1] == 'Y' && a2[1] == 'X', x_first = a1[1] == 'X' && a2[1] == 'Y';
  if (!y_first && !x_first) malformed(path, "not a Radiance .hdr file (resolution line '" + line.substr(0, 40) + "')");
  return y_first ? checked(path, n2, n1) : checked(path, n1, n2);
}

}  // namespace

cv::Size float_image_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) malformed(path, "cannot open");
  return lower_extension(path) == ".pfm" ? pfm_size(in, path) : hdr_size(in, path);
}

}  // namespace eyestream::io
