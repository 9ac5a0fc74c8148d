#include "io/exr_file.hpp"

#include <algorithm>

#include <cmath>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfCompression.h>
#include <OpenEXR/openexr.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>

#include <exception>
#include <string>
#include <vector>

#include "io/error.hpp"
#include "io/exr_chunks.hpp"
#include "io/half_rows.hpp"
#include "io/primaries.hpp"

namespace eyestream::io {

namespace {

Chromaticities from_imf(const Imf::Chromaticities& c) {
  return {c.red.x, c.red.y, c.green.x, c.green.y, c.blue.x, c.blue.y, c.white.x, c.white.y};
}

Imf::Chromaticities to_imf(const Chromaticities& c) {
  return Imf::Chromaticities(Imath::V2f(float(c.rx), float(c.ry)), Imath::V2f(float(c.gx), float(c.gy)),
                             Imath::V2f(float(c.bx), float(c.by)), Imath::V2f(float(c.wx), float(c.wy)));
}

// The channel layout of layer `prefix` ("" or "ViewLayer.Combined."):
// "RGBA", "RGB", "Y" or "".
std::string channel_layout(const Imf::ChannelList& ch, const std::string& prefix) {
  const auto has = [&](const char* c) { return ch.findChannel(prefix + c) != nullptr; };
  if (has("R") && has("G") && has("B")) return has("A") ? "RGBA" : "RGB";
  if (has("Y") && !has("X") && !has("Z")) return "Y";  // X, Y, Z: a vector (normals, positions), not light
  return "";
}

// The layers (channel-name prefixes before the last '.') holding R, G and B
// or Y, in the file's order; the unnamed root layer is "".
std::vector<std::string> colour_layers(const Imf::ChannelList& ch) {
  std::vector<std::string> layers;
  for (Imf::ChannelList::ConstIterator i = ch.begin(); i != ch.end(); ++i) {
    const std::string name = i.name();
    const size_t dot = name.rfind('.');
    const std::string layer = dot == std::string::npos ? "" : name.substr(0, dot);
    if (std::find(layers.begin(), layers.end(), layer) == layers.end() &&
        !channel_layout(ch, layer.empty() ? "" : layer + ".").empty())
      layers.push_back(layer);
  }
  return layers;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The layer to read: `wanted` when given; else the root layer, else the
// beauty pass (Blender's ...Combined, or a layer named beauty or RGBA),
// else the only colour layer. InputError listing the layers otherwise.
std::string choose_layer(const std::string& path, const Imf::ChannelList& ch, const std::string& wanted) {
  const std::vector<std::string> layers = colour_layers(ch);
  std::string list;
  for (const std::string& l : layers) list += (list.empty() ? "" : ", ") + (l.empty() ? std::string("(root)") : l);
  if (!wanted.empty()) {
    if (std::find(layers.begin(), layers.end(), wanted) != layers.end()) return wanted;
    throw InputError(path + ": no colour layer '" + wanted + "' (--layer); it holds " +
                     (list.empty() ? std::string("none") : list));
  }
  if (std::find(layers.begin(), layers.end(), "") != layers.end()) return "";
  std::vector<std::string> beauty;
  for (const std::string& l : layers)
    if (ends_with(l, "Combined") || ends_with(l, "beauty") || ends_with(l, "RGBA") || ends_with(l, "rgba"))
      beauty.push_back(l);
  if (beauty.size() == 1) return beauty.front();
  if (beauty.size() > 1) {  // Blender: one Combined per view layer
    std::string names;
    for (const std::string& l : beauty) names += (names.empty() ? "" : ", ") + l;
    throw InputError(path + ": several beauty passes (" + names + "); choose one with --layer");
  }
  if (layers.size() == 1) return layers.front();
  if (layers.empty()) throw InputError(path + ": no colour channels (R, G, B, or Y alone; X, Y, Z is a vector pass)");
  throw InputError(path + ": several colour layers (" + list + ") and no beauty pass; choose one with --layer");
}

// The data window from the header alone (OpenEXR's core library reads no
// more than the header), refused over max_pixels before the C++ library
// builds its tables for it.
void check_data_window(const std::string& path, std::int64_t max_pixels) {
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = [](exr_const_context_t, exr_result_t, const char*) {};  // reported below, once
  exr_context_t ctxt = nullptr;
  if (exr_start_read(&ctxt, path.c_str(), &init) != EXR_ERR_SUCCESS) {
    exr_finish(&ctxt);
    return;  // not readable as EXR: the C++ reader says why
  }
  exr_attr_box2i_t dw;
  const bool ok = exr_get_data_window(ctxt, 0, &dw) == EXR_ERR_SUCCESS;
  exr_finish(&ctxt);
  if (!ok) return;
  const std::int64_t width = std::int64_t(dw.max.x) - dw.min.x + 1, height = std::int64_t(dw.max.y) - dw.min.y + 1;
  if (width <= 0 || height <= 0 || width * height > max_pixels)
    throw InputError(path + ": data window " + std::to_string(width) + "x" + std::to_string(height) +
                     " (read from its header) exceeds the limit of " + std::to_string(max_pixels) +
                     " pixels (--max-pixels)");
}

// Scan lines compressed together (the OpenEXR file layout's table).
int lines_per_block(Imf::Compression c) {
  switch (c) {
    case Imf::ZIP_COMPRESSION:
    case Imf::PXR24_COMPRESSION: return 16;
    case Imf::PIZ_COMPRESSION:
    case Imf::B44_COMPRESSION:
    case Imf::B44A_COMPRESSION:
    case Imf::DWAA_COMPRESSION: return 32;
    case Imf::DWAB_COMPRESSION: return 256;
    default: return 1;
  }
}

}  // namespace

ExrImage read_exr(const std::string& path, std::int64_t max_pixels, const std::string& layer,
                  const ExrRowsHook& on_rows) {
  try {
    check_data_window(path, max_pixels);
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const Imath::Box2i dw = header.dataWindow();
    const std::int64_t width = std::int64_t(dw.max.x) - dw.min.x + 1;
    const std::int64_t height = std::int64_t(dw.max.y) - dw.min.y + 1;
    if (width <= 0 || height <= 0 || width * height > max_pixels)
      throw InputError(path + ": data window " + std::to_string(width) + "x" + std::to_string(height) +
                       " exceeds the limit of " + std::to_string(max_pixels) + " pixels (--max-pixels)");

    ExrImage image;
    image.layer = choose_layer(path, header.channels(), layer);
    const std::string prefix = image.layer.empty() ? "" : image.layer + ".";
    image.channels = channel_layout(header.channels(), prefix);
    // Metadata that would silently give black frames or absurd timing is
    // refused, naming the attribute (--scale and --fps override them).
    if (Imf::hasWhiteLuminance(header)) {
      const double white = Imf::whiteLuminance(header);
      if (!(white > 0.0) || !std::isfinite(white))
        throw InputError(path + ": whiteLuminance " + std::to_string(white) + " is not a positive luminance (--scale overrides it)");
      image.white_luminance = white;
    }
    if (Imf::hasChromaticities(header)) {
      image.chromaticities = from_imf(Imf::chromaticities(header));
      if (!valid_chromaticities(*image.chromaticities))
        throw InputError(path + ": chromaticities do not describe three independent primaries and a white");
    }
    if (Imf::hasFramesPerSecond(header)) {
      const Imf::Rational& r = Imf::framesPerSecond(header);
      const double fps = r.d != 0 ? double(r.n) / double(r.d) : 0.0;
      if (r.n > 0 && r.d != 0 && !(fps >= 0.01 && fps <= 10000.0))
        throw InputError(path + ": framesPerSecond " + std::to_string(fps) + " is outside 0.01-10000 (--fps overrides it)");
      if (r.d != 0 && r.n > 0) image.frames_per_second = fps;
    }

    image.rgb.create(int(height), int(width), CV_32FC3);
    const std::vector<std::string> names =
        image.channels == "Y" ? std::vector<std::string>{"Y"} : std::vector<std::string>{"R", "G", "B"};
    // Bands of whole line buffers (16 lines for ZIP, 32 for PIZ ...), each
    // finished while it is in cache.
    const int band = std::max(16, lines_per_block(header.compression()));
    // Half channels (most EXRs) are read as they are stored and made floats
    // here by vector loops (half_rows.hpp); others OpenEXR converts.
    bool halves = true;
    for (const std::string& name : names) {
      const Imf::Channel* c = header.channels().findChannel(prefix + name);
      halves = halves && c && c->type == Imf::HALF && c->xSampling == 1 && c->ySampling == 1;
    }
    // Halves in ZIP, ZIPS or uncompressed scanline chunks (most EXRs) are
    // decoded by the program (exr_chunks.hpp), others by OpenEXR.
    std::unique_ptr<ExrChunks> chunks = halves ? ExrChunks::open(file, path) : nullptr;
    std::ptrdiff_t offsets[3] = {-1, -1, -1};
    for (size_t c = 0; chunks && c < names.size(); ++c) offsets[c] = chunks->offset_of(prefix + names[c]);
    std::vector<std::uint16_t> stored(halves && !chunks ? names.size() * size_t(band) * size_t(width) : 0);
    const size_t plane = size_t(band) * size_t(width);  // one channel's halves in a band
    if (!halves) {
      const size_t xs = 3 * sizeof(float), ys = xs * size_t(width);
      char* base = reinterpret_cast<char*>(image.rgb.ptr<float>());
      Imf::FrameBuffer fb;
      for (size_t c = 0; c < names.size(); ++c)
        fb.insert(prefix + names[c], Imf::Slice::Make(Imf::FLOAT, base + c * sizeof(float), dw, xs, ys));
      file.setFrameBuffer(fb);
    }
    for (int y0 = dw.min.y; y0 <= dw.max.y; y0 += band) {
      const int y1 = int(std::min<std::int64_t>(std::int64_t(y0) + band - 1, dw.max.y));
      cv::Mat rows = image.rgb.rowRange(y0 - dw.min.y, y1 - dw.min.y + 1);
      if (chunks) {  // the band's chunks one at a time (a band is whole chunks)
        for (int y = y0; y <= y1;) {
          const int end = y + chunks->decode(y);
          CV_Assert(end <= y1 + 1);
          for (; y < end; ++y) {
            float* out = rows.ptr<float>(y - y0);
            if (names.size() == 1)
              halves_to_grey_rgb(chunks->samples(y, offsets[0]), out, int(width));
            else
              halves_to_rgb(chunks->samples(y, offsets[0]), chunks->samples(y, offsets[1]),
                            chunks->samples(y, offsets[2]), out, int(width));
          }
        }
        if (on_rows) on_rows(image, rows);
        continue;
      }
      if (halves) {
        const Imath::Box2i lines(Imath::V2i(dw.min.x, y0), Imath::V2i(dw.max.x, y1));
        Imf::FrameBuffer fb;
        for (size_t c = 0; c < names.size(); ++c)
          fb.insert(prefix + names[c], Imf::Slice::Make(Imf::HALF, stored.data() + c * plane, lines, sizeof(std::uint16_t),
                                                        sizeof(std::uint16_t) * size_t(width)));
        file.setFrameBuffer(fb);
      }
      file.readPixels(y0, y1);
      if (halves) {
        for (int y = 0; y < rows.rows; ++y) {
          const size_t at = size_t(y) * size_t(width);
          if (names.size() == 1)
            halves_to_grey_rgb(stored.data() + at, rows.ptr<float>(y), int(width));
          else
            halves_to_rgb(stored.data() + at, stored.data() + plane + at, stored.data() + 2 * plane + at,
                          rows.ptr<float>(y), int(width));
        }
      } else if (image.channels == "Y") {
        rows.forEach<cv::Vec3f>([](cv::Vec3f& p, const int*) { p[1] = p[2] = p[0]; });
      }
      if (on_rows) on_rows(image, rows);
    }
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path + ": cannot read EXR: " + e.what());
  }
}

namespace {

Imf::Compression imf_compression(ExrCompression c) {
  switch (c) {
    case ExrCompression::kNone: return Imf::NO_COMPRESSION;
    case ExrCompression::kRle: return Imf::RLE_COMPRESSION;
    case ExrCompression::kZips: return Imf::ZIPS_COMPRESSION;
    case ExrCompression::kZip: break;
    case ExrCompression::kPiz: return Imf::PIZ_COMPRESSION;
  }
  return Imf::ZIP_COMPRESSION;
}

}  // namespace

ExrCompression exr_compression_named(const std::string& name) {
  if (name == "none") return ExrCompression::kNone;
  if (name == "rle") return ExrCompression::kRle;
  if (name == "zips") return ExrCompression::kZips;
  if (name == "zip") return ExrCompression::kZip;
  if (name == "piz") return ExrCompression::kPiz;
  throw UsageError("--exr-compression " + name + ": unknown (none, rle, zips, zip or piz)");
}

void write_exr(const std::string& path, const cv::Mat& rgb, const ExrWriteOptions& options) {
  CV_Assert(rgb.type() == CV_32FC3 && rgb.isContinuous());
  try {
    Imf::Header header(rgb.cols, rgb.rows);
    header.compression() = imf_compression(options.compression);
    const Imf::PixelType type = options.half ? Imf::HALF : Imf::FLOAT;
    for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(type));
    Imf::addChromaticities(header, to_imf(rec709_chromaticities()));
    if (options.white_luminance) Imf::addWhiteLuminance(header, float(*options.white_luminance));
    if (options.frames_per_second) Imf::addFramesPerSecond(header, Imf::Rational(*options.frames_per_second));

    Imf::OutputFile file(path.c_str(), header);
    // Slices must match the channel type: convert to half here when asked.
    std::vector<Imath::half> halves;
    const char* base = reinterpret_cast<const char*>(rgb.ptr<float>());
    size_t xs = 3 * sizeof(float);
    if (options.half) {
      const float* src = rgb.ptr<float>();
      halves.assign(src, src + rgb.total() * 3);
      base = reinterpret_cast<const char*>(halves.data());
      xs = 3 * sizeof(Imath::half);
    }
    const size_t ys = xs * size_t(rgb.cols), cs = xs / 3;
    char* b = const_cast<char*>(base);
    Imf::FrameBuffer fb;
    fb.insert("R", Imf::Slice(type, b, xs, ys));
    fb.insert("G", Imf::Slice(type, b + cs, xs, ys));
    fb.insert("B", Imf::Slice(type, b + 2 * cs, xs, ys));
    file.setFrameBuffer(fb);
    file.writePixels(rgb.rows);
  } catch (const std::exception& e) {
    throw OutputError(path + ": cannot write EXR: " + e.what());
  }
}

void write_exr_channels(const std::string& path, const std::vector<std::pair<std::string, cv::Mat>>& planes) {
  CV_Assert(!planes.empty());
  const cv::Size size = planes.front().second.size();
  try {
    Imf::Header header(size.width, size.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const auto& [name, plane] : planes) {
      CV_Assert(plane.type() == CV_32F && plane.size() == size && plane.isContinuous());
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    }
    Imf::OutputFile file(path.c_str(), header);
    Imf::FrameBuffer fb;
    for (const auto& [name, plane] : planes)
      fb.insert(name, Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(plane.ptr<float>())),
                                 sizeof(float), sizeof(float) * size_t(size.width)));
    file.setFrameBuffer(fb);
    file.writePixels(size.height);
  } catch (const std::exception& e) {
    throw OutputError(path + ": cannot write EXR: " + e.what());
  }
}

}  // namespace eyestream::io
