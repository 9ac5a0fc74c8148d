#include "io/radiance_hdr.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "io/error.hpp"

namespace eyestream::io {

namespace {

// The file's bytes with a read position; every read is bounded.
struct Bytes {
  std::vector<unsigned char> data;
  size_t at = 0;
  bool line(std::string& out) {
    out.clear();
    while (at < data.size() && data[at] != '\n') out.push_back(char(data[at++]));
    if (at >= data.size()) return false;
    ++at;
    if (!out.empty() && out.back() == '\r') out.pop_back();  // a header written with CR LF
    return true;
  }
  size_t left() const { return data.size() - at; }
};

// One scanline of `width` RGBE pixels into `rgbe` (4 width bytes);
// false when the data is short or its runs overflow the line.
bool read_scanline(Bytes& in, int width, unsigned char* rgbe) {
  const bool rle = width >= 8 && width < 0x8000 && in.left() >= 4 && in.data[in.at] == 2 &&
                   in.data[in.at + 1] == 2 && !(in.data[in.at + 2] & 0x80);
  if (!rle) {  // flat pixels
    if (in.left() < size_t(width) * 4) return false;
    std::memcpy(rgbe, &in.data[in.at], size_t(width) * 4);
    in.at += size_t(width) * 4;
    return true;
  }
  if ((int(in.data[in.at + 2]) << 8 | in.data[in.at + 3]) != width) return false;
  in.at += 4;
  // Each component's runs in turn: a count above 128 repeats the next
  // byte count - 128 times, else count bytes follow as they are.
  for (int c = 0; c < 4; ++c)
    for (int x = 0; x < width;) {
      if (in.left() < 1) return false;
      int count = in.data[in.at++];
      if (count > 128) {
        count -= 128;
        if (count > width - x || in.left() < 1) return false;
        const unsigned char v = in.data[in.at++];
        for (int k = 0; k < count; ++k) rgbe[4 * (x + k) + c] = v;
      } else {
        if (count == 0 || count > width - x || in.left() < size_t(count)) return false;
        for (int k = 0; k < count; ++k) rgbe[4 * (x + k) + c] = in.data[in.at++];
      }
      x += count;
    }
  return true;
}

// The file, read on demand: the header from its first MiB, the pixels
// only once the declared size has been checked.
struct RadianceFile {
  std::ifstream file;
  std::streamoff size = 0;
  Bytes in;
  explicit RadianceFile(const std::string& path) : file(path, std::ios::binary | std::ios::ate) {
    if (!file) throw InputError(path + ": cannot open");
    size = file.tellg();
    if (size < 0) throw InputError(path + ": cannot read its size");
    file.seekg(0);
    read_to(std::streamoff(1) << 20, path);
  }
  void read_to(std::streamoff end, const std::string& path) {
    const size_t have = in.data.size(), want = size_t(std::min(end, size));
    if (want <= have) return;
    in.data.resize(want);
    if (!file.read(reinterpret_cast<char*>(in.data.data() + have), std::streamsize(want - have)))
      throw InputError(path + ": cannot read");
  }
};

// The header's lines up to the empty one and the resolution line; the
// declared width and height, leaving `in` at the first scanline.
cv::Size parse_header(Bytes& in, const std::string& path) {
  std::string line;
  if (!in.line(line) || line.rfind("#?", 0) != 0) throw InputError(path + ": not a Radiance .hdr file");
  while (in.line(line) && !line.empty())
    if (line.rfind("FORMAT=", 0) == 0 && line != "FORMAT=32-bit_rle_rgbe")
      throw InputError(path + ": holds " + line.substr(7, 40) + " pixels; eyestream reads 32-bit_rle_rgbe (RGB)");
  std::string y_axis, x_axis;
  long long height = 0, width = 0;
  std::istringstream resolution(in.line(line) ? line : std::string());
  if (!(resolution >> y_axis >> height >> x_axis >> width) || y_axis != "-Y" || x_axis != "+X")
    throw InputError(path + ": the resolution line is not '-Y height +X width' (rows from the top, columns from the "
                            "left): '" + line.substr(0, 40) + "'");
  if (width <= 0 || height <= 0 || width > 1000000 || height > 1000000)
    throw InputError(path + ": declares a size of " + std::to_string(width) + "x" + std::to_string(height));
  return {int(width), int(height)};
}

}  // namespace

cv::Size radiance_hdr_size(const std::string& path) {
  RadianceFile f(path);
  return parse_header(f.in, path);
}

cv::Mat read_radiance_hdr(const std::string& path, std::int64_t max_pixels) {
  RadianceFile f(path);
  Bytes& in = f.in;
  const cv::Size declared = parse_header(in, path);
  const long long width = declared.width, height = declared.height;
  if (width * height > max_pixels)
    throw InputError(path + ": " + std::to_string(width) + "x" + std::to_string(height) + " exceeds the limit of " +
                     std::to_string(max_pixels) + " pixels");
  // Each scanline at most: its marker, then every component's values with a
  // count byte before each 128.
  f.read_to(std::streamoff(in.at) + std::streamoff(height) * (4 + 4 * width + 4 * ((width + 127) / 128)), path);
  cv::Mat rgb(int(height), int(width), CV_32FC3);
  std::vector<unsigned char> rgbe(size_t(width) * 4);
  for (int y = 0; y < rgb.rows; ++y) {
    if (!read_scanline(in, int(width), rgbe.data()))
      throw InputError(path + ": damaged or short pixel data at scanline " + std::to_string(y));
    cv::Vec3f* out = rgb.ptr<cv::Vec3f>(y);
    for (int x = 0; x < rgb.cols; ++x) {
      const unsigned char* p = &rgbe[size_t(x) * 4];
      const float f = p[3] ? std::ldexp(1.0f, int(p[3]) - (128 + 8)) : 0.0f;
      out[x] = cv::Vec3f(p[0] * f, p[1] * f, p[2] * f);
    }
  }
  return rgb;
}

}  // namespace eyestream::io
