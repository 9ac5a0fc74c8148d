#include "io/pfm_file.hpp"

#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <vector>

#include "io/error.hpp"

namespace eyestream::io {

namespace {

// The next whitespace-separated word of the header, and the one
// whitespace byte after it consumed (the last one ends the header).
bool word(std::istream& in, std::string& out) {
  out.clear();
  int c = in.get();
  while (c != EOF && std::isspace(c)) c = in.get();
  while (c != EOF && !std::isspace(c) && out.size() < 64) out.push_back(char(c)), c = in.get();
  return !out.empty() && c != EOF;
}

struct Header {
  long long width = 0, height = 0;
  int channels = 3;
  double scale = 0.0;
};

// The header's four words, checked; `in` is left at the first pixel.
Header parse_header(std::istream& in, const std::string& path) {
  std::string magic, w, h, s;
  if (!word(in, magic) || (magic != "PF" && magic != "Pf") || !word(in, w) || !word(in, h) || !word(in, s))
    throw InputError(path + ": not a PFM file");
  long long width = 0, height = 0;
  double scale = 0.0;
  try {
    size_t used_w = 0, used_h = 0, used_s = 0;
    width = std::stoll(w, &used_w);
    height = std::stoll(h, &used_h);
    scale = std::stod(s, &used_s);
    if (used_w != w.size() || used_h != h.size() || used_s != s.size()) throw std::invalid_argument(s);
  } catch (const std::exception&) {
    throw InputError(path + ": not a PFM file (header '" + magic + " " + w + " " + h + " " + s + "')");
  }
  if (width <= 0 || height <= 0 || width > 1000000 || height > 1000000)
    throw InputError(path + ": declares a size of " + std::to_string(width) + "x" + std::to_string(height));
  if (!std::isfinite(scale) || scale == 0.0) throw InputError(path + ": the scale " + s + " is not a non-zero number");
  return {width, height, magic == "PF" ? 3 : 1, scale};
}

}  // namespace

cv::Size pfm_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open");
  const Header h = parse_header(in, path);
  return {int(h.width), int(h.height)};
}

cv::Mat read_pfm(const std::string& path, std::int64_t max_pixels) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open");
  const Header h = parse_header(in, path);
  const long long width = h.width, height = h.height;
  const int channels = h.channels;
  if (width * height > max_pixels)
    throw InputError(path + ": " + std::to_string(width) + "x" + std::to_string(height) + " exceeds the limit of " +
                     std::to_string(max_pixels) + " pixels");
  const bool little = h.scale < 0.0;
  const float times = 1.0f / float(std::fabs(h.scale));  // as OpenCV applied it, to the same floats
  std::vector<unsigned char> row(size_t(width) * size_t(channels) * 4);
  cv::Mat rgb(int(height), int(width), CV_32FC3);
  for (int y = rgb.rows - 1; y >= 0; --y) {  // the file's first row is the bottom one
    if (!in.read(reinterpret_cast<char*>(row.data()), std::streamsize(row.size())))
      throw InputError(path + ": short pixel data at row " + std::to_string(rgb.rows - 1 - y) + " from the bottom");
    cv::Vec3f* out = rgb.ptr<cv::Vec3f>(y);
    for (int x = 0; x < rgb.cols; ++x)
      for (int c = 0; c < 3; ++c) {
        const unsigned char* b = &row[(size_t(x) * size_t(channels) + size_t(channels == 3 ? c : 0)) * 4];
        const std::uint32_t bits = little ? std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 |
                                                std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24
                                          : std::uint32_t(b[3]) | std::uint32_t(b[2]) << 8 |
                                                std::uint32_t(b[1]) << 16 | std::uint32_t(b[0]) << 24;
        float v;
        std::memcpy(&v, &bits, 4);
        out[x][c] = v * times;
      }
  }
  return rgb;
}

}  // namespace eyestream::io
