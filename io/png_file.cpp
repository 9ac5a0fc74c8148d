#include "io/png_file.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "io/error.hpp"
#include "io/staged_file.hpp"

namespace eyestream::io {

namespace {

// CRC-32 of PNG chunks (ISO 3309, the polynomial 0xEDB88320, reflected).
std::uint32_t crc32_of(const unsigned char* data, size_t n) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) c = table[(c ^ data[i]) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void put32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>(v >> shift));
}

// A chunk: length, type, data, CRC over type and data.
std::vector<unsigned char> chunk(const char type[4], const std::vector<std::uint32_t>& words) {
  std::vector<unsigned char> c;
  put32(c, std::uint32_t(4 * words.size()));
  c.insert(c.end(), type, type + 4);
  for (std::uint32_t w : words) put32(c, w);
  put32(c, crc32_of(c.data() + 4, c.size() - 4));
  return c;
}

}  // namespace

std::vector<unsigned char> encode_png(const cv::Mat& bgr, double gamma) {
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", bgr, png)) return {};
  // After the signature (8 bytes) and IHDR (4 + 4 + 13 + 4): the display
  // encoding's power (retina/display_encoding.hpp), and the Rec.709
  // primaries with D65, in units of 1e-5.
  constexpr size_t kAfterHeader = 8 + 25;
  if (png.size() < kAfterHeader) return png;
  const std::vector<unsigned char> gama = chunk("gAMA", {std::uint32_t(std::lround(gamma * 100000))});
  const std::vector<unsigned char> chrm =
      chunk("cHRM", {31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000});
  png.insert(png.begin() + kAfterHeader, chrm.begin(), chrm.end());
  png.insert(png.begin() + kAfterHeader, gama.begin(), gama.end());
  return png;
}

StagedFile stage_png(const std::filesystem::path& path, const cv::Mat& bgr) {
  const std::vector<unsigned char> png = encode_png(bgr);
  if (png.empty()) throw OutputError(path.string() + ": PNG encoding failed");
  StagedFile file(path);
  write_all(file, png);
  return file;
}

void write_png(const std::filesystem::path& path, const cv::Mat& bgr) { stage_png(path, bgr).commit(); }

}  // namespace eyestream::io
