#include "io/png_file.hpp"

#include <png.h>
#include <zlib.h>

#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <memory>

#include "io/error.hpp"

namespace eyestream::io {

namespace {

// libpng reports an error by longjmp to the setjmp in the function that
// called it; these functions hold no C++ object with a destructor between
// the setjmp and the calls that may jump, so nothing is skipped. Neither
// errors nor warnings are printed: a failure is named by eyestream's own
// line.
void no_warning(png_structp, png_const_charp) {}
[[noreturn]] void quiet_error(png_structp png, png_const_charp) { png_longjmp(png, 1); }

// Appends to the vector; a failure to grow it is libpng's error, raised
// after the C++ handler has ended (no exception crosses libpng's frames).
void append_bytes(png_structp png, png_bytep data, png_size_t n) {
  bool grown = true;
  try {
    auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + n);
  } catch (...) {
    grown = false;
  }
  if (!grown) png_error(png, "out of memory");
}

void no_flush(png_structp) {}

// Writes the rows of `m` into `out`; false when libpng failed.
bool write_rows(const cv::Mat& m, double gamma, std::vector<unsigned char>* out, png_bytep* rows) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, quiet_error, no_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, out, append_bytes, no_flush);
  // OpenCV 4.6's settings when given no parameters.
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_compression_level(png, Z_BEST_SPEED);
  png_set_compression_strategy(png, Z_RLE);
  const int depth = m.depth() == CV_16U ? 16 : 8;
  png_set_IHDR(png, info, png_uint_32(m.cols), png_uint_32(m.rows), depth,
               m.channels() == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  // The display encoding's power, and the Rec.709 primaries with D65, in
  // units of 1e-5.
  png_set_gAMA_fixed(png, info, png_fixed_point(std::lround(gamma * 100000)));
  png_set_cHRM_fixed(png, info, 31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000);
  png_write_info(png, info);
  if (m.channels() == 3) png_set_bgr(png);
  if (depth == 16) png_set_swap(png);  // the samples are held little-endian
  png_write_image(png, rows);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

// Reads the header, then the pixels into the rows that
// `allocate(width, height, channels, depth)` gives once the size is known
// (null: refused, the caller says why); the message of the failure, or
// empty.
template <typename Allocate>
std::string read_rows(std::FILE* file, Allocate&& allocate) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, quiet_error, no_warning);
  if (!png) return "cannot start the PNG decoder";
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_read_struct(&png, &info, nullptr);
    return "cannot start the PNG decoder";
  }
  const char* volatile failure = "not a PNG file, or a damaged one";  // volatile: read after a longjmp
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return failure;
  }
  png_init_io(png, file);
  png_set_crc_action(png, PNG_CRC_DEFAULT, PNG_CRC_DEFAULT);
  png_read_info(png, info);
  const int depth = png_get_bit_depth(png, info), colour = png_get_color_type(png, info);
  // Palettes to RGB, grey below 8 bits to 8, alpha dropped, 16-bit
  // samples to the machine's order; interlaced images are put together.
  if (colour == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (colour == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if ((colour & PNG_COLOR_MASK_ALPHA) || png_get_valid(png, info, PNG_INFO_tRNS)) png_set_strip_alpha(png);
  if (depth == 16) png_set_swap(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  // The caller's allocation may throw: the decoder is destroyed first (no
  // longjmp can cross this handler: libpng is not called inside it).
  png_bytep* rows = nullptr;
  try {
    rows = allocate(png_get_image_width(png, info), png_get_image_height(png, info), int(png_get_channels(png, info)),
                    int(png_get_bit_depth(png, info)));
  } catch (...) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw;
  }
  if (!rows) {
    png_destroy_read_struct(&png, &info, nullptr);
    return "";  // refused by the caller, which says why
  }
  failure = "damaged image data";
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return "";
}

}  // namespace

std::vector<unsigned char> encode_png(const cv::Mat& bgr, double gamma) {
  if (bgr.empty() || (bgr.depth() != CV_8U && bgr.depth() != CV_16U) || (bgr.channels() != 1 && bgr.channels() != 3))
    return {};
  std::vector<png_bytep> rows(size_t(bgr.rows));
  for (int y = 0; y < bgr.rows; ++y) rows[size_t(y)] = const_cast<png_bytep>(bgr.ptr<png_byte>(y));
  std::vector<unsigned char> out;
  if (!write_rows(bgr, gamma, &out, rows.data())) return {};
  return out;
}

StagedFile stage_png(const std::filesystem::path& path, const cv::Mat& bgr) {
  const std::vector<unsigned char> png = encode_png(bgr);
  if (png.empty()) throw OutputError(path.string() + ": PNG encoding failed");
  StagedFile file(path);
  write_all(file, png);
  return file;
}

void write_png(const std::filesystem::path& path, const cv::Mat& bgr) { stage_png(path, bgr).commit(); }

cv::Mat read_png(const std::string& path, std::int64_t max_pixels) {
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) throw InputError(path + ": cannot open");
  cv::Mat image;
  std::vector<png_bytep> rows;
  std::string refused;
  const auto allocate = [&](png_uint_32 width, png_uint_32 height, int channels, int depth) -> png_bytep* {
    if (width == 0 || height == 0 || width > 1000000 || height > 1000000 ||
        std::int64_t(width) * std::int64_t(height) > max_pixels) {
      refused = "a " + std::to_string(width) + "x" + std::to_string(height) + " PNG exceeds the limit of " +
                std::to_string(max_pixels) + " pixels";
      return nullptr;
    }
    if (channels != 1 && channels != 3) {
      refused = "a PNG of " + std::to_string(channels) + " samples a pixel";
      return nullptr;
    }
    image.create(int(height), int(width), CV_MAKETYPE(depth == 16 ? CV_16U : CV_8U, channels));
    rows.resize(size_t(height));
    for (int y = 0; y < image.rows; ++y) rows[size_t(y)] = image.ptr<png_byte>(y);
    return rows.data();
  };
  const std::string failure = read_rows(file.get(), allocate);
  if (!refused.empty()) throw InputError(path + ": " + refused);
  if (!failure.empty()) throw InputError(path + ": " + failure);
  return image;
}

}  // namespace eyestream::io
