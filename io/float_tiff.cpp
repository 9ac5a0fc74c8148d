#include "io/float_tiff.hpp"

#include <Imath/half.h>
#include <tiffio.h>

#include <cstdarg>
#include <cstdio>
#include <memory>
#include <mutex>
#include <vector>

#include "io/error.hpp"

namespace eyestream::io {

namespace {

// libtiff reports through global handlers; they are silenced here and the
// failure is named by the caller (one line on stderr, eyestream's own).
void quiet(const char*, const char*, va_list) {}

struct TiffCloser {
  void operator()(TIFF* t) const { TIFFClose(t); }
};

// One sample as float, from 32- or 16-bit IEEE storage, or from 8- or
// 16-bit unsigned codes (`codes`) over their largest value.
float sample(const unsigned char* data, size_t index, int bits, bool codes) {
  if (codes)
    return bits == 8 ? float(data[index]) * (1.0f / 255.0f)
                     : float(reinterpret_cast<const std::uint16_t*>(data)[index]) * (1.0f / 65535.0f);
  if (bits == 32) return reinterpret_cast<const float*>(data)[index];
  Imath::half h;
  h.setBits(reinterpret_cast<const std::uint16_t*>(data)[index]);
  return float(h);
}

// Display codes of 8 bits or fewer in any photometric interpretation
// (grey, either way round, palette, RGB, YCbCr, CMYK, one bit a pixel),
// through libtiff's RGBA conversion, as OpenCV read them: R, G, B over 255,
// turned upright by the Orientation tag and multiplied by an unassociated
// alpha, as that conversion does (16-bit codes, read sample by sample
// below, are neither: as OpenCV's reader, too).
cv::Mat rgba_codes(TIFF* tif, const std::string& path, std::uint32_t width, std::uint32_t height) {
  char message[1024] = "";
  if (!TIFFRGBAImageOK(tif, message)) throw InputError(path + ": cannot read as a picture: " + message);
  std::vector<std::uint32_t> raster(size_t(width) * height);
  if (!TIFFReadRGBAImageOriented(tif, width, height, raster.data(), ORIENTATION_TOPLEFT, 1))
    throw InputError(path + ": damaged image data");
  cv::Mat rgb(int(height), int(width), CV_32FC3);
  for (int y = 0; y < rgb.rows; ++y) {
    const std::uint32_t* in = &raster[size_t(y) * width];
    cv::Vec3f* out = rgb.ptr<cv::Vec3f>(y);
    for (int x = 0; x < rgb.cols; ++x)
      out[x] = cv::Vec3f(float(TIFFGetR(in[x])), float(TIFFGetG(in[x])), float(TIFFGetB(in[x]))) * (1.0f / 255.0f);
  }
  return rgb;
}

cv::Mat read_tiff(const std::string& path, bool codes, std::int64_t max_pixels) {
  static std::once_flag silenced;
  std::call_once(silenced, [] {
    TIFFSetErrorHandler(quiet);
    TIFFSetWarningHandler(quiet);
  });
  std::unique_ptr<TIFF, TiffCloser> tif(TIFFOpen(path.c_str(), "r"));
  if (!tif) throw InputError(path + ": cannot open as a TIFF file");
  std::uint32_t width = 0, height = 0;
  std::uint16_t bits = 0, channels = 1, format = SAMPLEFORMAT_UINT, planar = PLANARCONFIG_CONTIG;
  TIFFGetField(tif.get(), TIFFTAG_IMAGEWIDTH, &width);
  TIFFGetField(tif.get(), TIFFTAG_IMAGELENGTH, &height);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_BITSPERSAMPLE, &bits);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_SAMPLESPERPIXEL, &channels);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_SAMPLEFORMAT, &format);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_PLANARCONFIG, &planar);
  std::uint16_t photometric = 0;
  TIFFGetField(tif.get(), TIFFTAG_PHOTOMETRIC, &photometric);
  if (photometric == PHOTOMETRIC_LOGLUV || photometric == PHOTOMETRIC_LOGL)
    throw InputError(path + ": a LogLuv TIFF (log-encoded CIE XYZ); eyestream reads 16- or 32-bit floating-point "
                            "RGB or grey TIFFs: convert it to float RGB first");
  if (width == 0 || height == 0) throw InputError(path + ": has no pixels");
  if (std::int64_t(width) * std::int64_t(height) > max_pixels)
    throw InputError(path + ": " + std::to_string(width) + "x" + std::to_string(height) + " exceeds the limit of " +
                     std::to_string(max_pixels) + " pixels");
  if (codes && format == SAMPLEFORMAT_UINT && bits <= 8) return rgba_codes(tif.get(), path, width, height);
  if (codes && (format != SAMPLEFORMAT_UINT || bits != 16))
    throw InputError(path + ": holds " + std::to_string(bits) + "-bit " +
                     (format == SAMPLEFORMAT_IEEEFP ? "floating-point" : "signed or other") +
                     " samples; display frames are read as unsigned codes of up to 16 bits");
  if (codes && photometric != PHOTOMETRIC_MINISBLACK && photometric != PHOTOMETRIC_RGB)
    throw InputError(path + ": 16-bit samples in photometric interpretation " + std::to_string(photometric) +
                     "; 16-bit display frames are read as grey (black at 0) or RGB");
  if (!codes && (format != SAMPLEFORMAT_IEEEFP || (bits != 32 && bits != 16)))
    throw InputError(path + ": holds " + std::to_string(bits) + "-bit " +
                     (format == SAMPLEFORMAT_IEEEFP ? "floating-point" : "integer") +
                     " samples; eyestream reads 16- or 32-bit floating-point TIFFs (linear light)");
  if (channels < 1 || channels > 4)
    throw InputError(path + ": holds " + std::to_string(channels) + " samples a pixel (expected grey, RGB, +alpha)");
  const int colour = channels >= 3 ? 3 : 1;  // the 2nd (grey) or 4th (RGB) is alpha
  const size_t bytes = bits / 8;
  cv::Mat rgb(int(height), int(width), CV_32FC3);
  // Each sample plane (planar) or the interleaved pixels, read in libtiff's
  // own units (tiles or strips), then placed.
  const int planes = planar == PLANARCONFIG_SEPARATE ? channels : 1;
  const int per_pixel = planar == PLANARCONFIG_SEPARATE ? 1 : channels;
  const bool tiled = TIFFIsTiled(tif.get());
  std::uint32_t unit_w = width, unit_h = 0;
  if (tiled) {
    TIFFGetField(tif.get(), TIFFTAG_TILEWIDTH, &unit_w);
    TIFFGetField(tif.get(), TIFFTAG_TILELENGTH, &unit_h);
  } else {
    TIFFGetFieldDefaulted(tif.get(), TIFFTAG_ROWSPERSTRIP, &unit_h);
    unit_h = std::min(unit_h, height);
  }
  if (unit_w == 0 || unit_h == 0) throw InputError(path + ": has no tile or strip size");
  const tmsize_t unit_size = tiled ? TIFFTileSize(tif.get()) : TIFFStripSize(tif.get());
  std::vector<unsigned char> buffer(static_cast<size_t>(unit_size));
  for (int plane = 0; plane < planes; ++plane)
    for (std::uint32_t y0 = 0; y0 < height; y0 += unit_h)
      for (std::uint32_t x0 = 0; x0 < width; x0 += unit_w) {
        const tmsize_t got =
            tiled ? TIFFReadTile(tif.get(), buffer.data(), x0, y0, 0, std::uint16_t(plane))
                  : TIFFReadEncodedStrip(tif.get(), TIFFComputeStrip(tif.get(), y0, std::uint16_t(plane)),
                                         buffer.data(), unit_size);
        if (got < 0)
          throw InputError(path + ": cannot decode the " + (tiled ? "tile" : "strip") + " at row " +
                           std::to_string(y0) + (tiled ? ", column " + std::to_string(x0) : std::string()));
        const std::uint32_t rows = std::min(unit_h, height - y0), cols = std::min(unit_w, width - x0);
        if (size_t(got) < size_t((rows - 1) * unit_w + cols) * size_t(per_pixel) * bytes)
          throw InputError(path + ": a " + (tiled ? "tile" : "strip") + " at row " + std::to_string(y0) + " is short");
        for (std::uint32_t r = 0; r < rows; ++r) {
          cv::Vec3f* out = rgb.ptr<cv::Vec3f>(int(y0 + r)) + x0;
          for (std::uint32_t c = 0; c < cols; ++c) {
            const size_t at = (size_t(r) * unit_w + c) * size_t(per_pixel);
            if (planes > 1) {
              if (plane < colour) out[c][plane] = sample(buffer.data(), at, bits, codes);
              if (colour == 1 && plane == 0) out[c][1] = out[c][2] = out[c][0];
            } else {
              for (int k = 0; k < colour; ++k) out[c][k] = sample(buffer.data(), at + size_t(k), bits, codes);
              if (colour == 1) out[c][1] = out[c][2] = out[c][0];
            }
          }
        }
      }
  return rgb;
}

}  // namespace

cv::Mat read_float_tiff(const std::string& path, std::int64_t max_pixels) { return read_tiff(path, false, max_pixels); }

cv::Mat read_code_tiff(const std::string& path, std::int64_t max_pixels) { return read_tiff(path, true, max_pixels); }

}  // namespace eyestream::io
