#include "io/exr_chunks.hpp"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfVersion.h>
#include <zlib.h>

#include <opencv2/core.hpp>

#include <algorithm>
#include <cstring>

#include "io/error.hpp"
#include "io/exr_zip_bytes.hpp"

namespace eyestream::io {

// The samples are used as stored: little-endian, as on x86-64 and AArch64.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "EXR samples are little-endian");

std::unique_ptr<ExrChunks> ExrChunks::open(Imf::InputFile& file, const std::string& path) {
  const Imf::Header& header = file.header();
  if (header.hasTileDescription() || !file.isComplete()) return nullptr;  // a missing chunk: readPixels says which
  if (Imf::isMultiPart(file.version())) return nullptr;  // each chunk also names its part
  if (header.hasType() && header.type() != Imf::SCANLINEIMAGE) return nullptr;
  const Imf::Compression c = header.compression();
  if (c != Imf::ZIP_COMPRESSION && c != Imf::ZIPS_COMPRESSION && c != Imf::NO_COMPRESSION) return nullptr;
  const Imath::Box2i dw = header.dataWindow();
  const size_t width = size_t(std::int64_t(dw.max.x) - dw.min.x + 1);
  std::unique_ptr<ExrChunks> chunks(new ExrChunks(file, path));
  // A line holds each channel's samples in turn, in the order of their
  // names (the channel list's order).
  for (Imf::ChannelList::ConstIterator i = header.channels().begin(); i != header.channels().end(); ++i) {
    const Imf::Channel& ch = i.channel();
    if (ch.xSampling != 1 || ch.ySampling != 1) return nullptr;
    chunks->offsets_.emplace_back(i.name(), chunks->line_bytes_);
    chunks->line_bytes_ += width * (ch.type == Imf::HALF ? 2 : 4);
  }
  if (chunks->offsets_.empty()) return nullptr;
  chunks->compression_ = c;
  chunks->lines_per_chunk_ = c == Imf::ZIP_COMPRESSION ? 16 : 1;
  chunks->min_y_ = dw.min.y;
  chunks->max_y_ = dw.max.y;
  return chunks;
}

std::ptrdiff_t ExrChunks::offset_of(const std::string& name) const {
  for (const auto& [n, offset] : offsets_)
    if (n == name) return std::ptrdiff_t(offset);
  return -1;
}

int ExrChunks::decode(int y) {
  CV_Assert(y >= min_y_ && y <= max_y_ && (y - min_y_) % lines_per_chunk_ == 0);
  first_line_ = y;
  const int count = std::min(lines_per_chunk_, max_y_ - y + 1);
  const size_t expected = size_t(count) * line_bytes_;
  line_.resize((expected + 1) / 2);
  unsigned char* out = reinterpret_cast<unsigned char*>(line_.data());
  const char* data = nullptr;
  int size = 0;
  file_.rawPixelData(y, data, size);
  // As OpenEXR: a chunk no smaller than its lines' bytes is stored as it
  // is (deflate would not have made it smaller); its first bytes are read.
  if (size > 0 && size_t(size) >= expected) {
    std::memcpy(out, data, expected);
    return count;
  }
  if (compression_ == Imf::NO_COMPRESSION || size <= 0)
    throw InputError(path_ + ": cannot read EXR: the chunk at line " + std::to_string(y) + " holds " +
                     std::to_string(size) + " bytes for " + std::to_string(expected));
  inflated_.resize(expected);
  uLongf length = uLongf(expected);
  if (uncompress(inflated_.data(), &length, reinterpret_cast<const Bytef*>(data), uLong(size)) != Z_OK ||
      length != expected)
    throw InputError(path_ + ": cannot read EXR: the chunk at line " + std::to_string(y) +
                     " does not inflate to its lines' " + std::to_string(expected) + " bytes");
  undo_zip_predictor(inflated_.data(), expected);
  undo_zip_reorder(inflated_.data(), out, expected);
  return count;
}

}  // namespace eyestream::io
