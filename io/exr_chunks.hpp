// A scanline EXR's ZIP, ZIPS and uncompressed chunks, decoded by the
// program rather than by OpenEXR's readPixels. OpenEXR still finds each
// chunk (InputFile::rawPixelData: the offset table, the chunk's header and
// its checks); zlib's `uncompress` inflates it (libdeflate in the program:
// zlib_uncompress.cpp); the ZIP predictor and byte order are then undone
// by vector loops (exr_zip_bytes.hpp). OpenEXR 3.1 undoes the predictor a
// byte at a time, a chain of dependent adds that took about a twentieth of
// a `fast` run's CPU (docs/performance.md). tests/exr_chunks_test.cpp holds
// the decoded samples to OpenEXR's own readPixels, byte for byte.
#pragma once

#include <OpenEXR/ImfCompression.h>
#include <OpenEXR/ImfInputFile.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace eyestream::io {

class ExrChunks {
 public:
  // Null unless `file` is a single-part scanline image with ZIP, ZIPS or
  // no compression whose channels are all sampled at every pixel (others
  // are left to readPixels). `path` names the file in errors.
  static std::unique_ptr<ExrChunks> open(Imf::InputFile& file, const std::string& path);

  // Decodes the chunk whose first line is y (the data window's first line
  // plus a whole number of chunks: ZIP's hold 16 lines, the others' 1, the
  // last may hold fewer) and returns how many lines it holds:
  // one chunk's bytes at a time, as OpenEXR holds them. InputError naming
  // the file and the line when a chunk does not inflate to its lines.
  int decode(int y);

  // Where channel `name`'s samples of a line start in that line's bytes;
  // -1 for a channel the file does not have.
  std::ptrdiff_t offset_of(const std::string& name) const;

  // Line y's bytes (within the last decoded chunk) at `offset`: the channel's
  // samples as stored (little-endian halves, floats or unsigned ints).
  // 2-byte aligned.
  const std::uint16_t* samples(int y, std::ptrdiff_t offset) const {
    return line_.data() + (size_t(y - first_line_) * line_bytes_ + size_t(offset)) / 2;
  }

 private:
  ExrChunks(Imf::InputFile& file, const std::string& path) : file_(file), path_(path) {}

  Imf::InputFile& file_;
  std::string path_;
  Imf::Compression compression_ = Imf::NO_COMPRESSION;
  int lines_per_chunk_ = 1;
  int min_y_ = 0, max_y_ = 0;
  size_t line_bytes_ = 0;
  std::vector<std::pair<std::string, size_t>> offsets_;  // each channel's offset in a line
  int first_line_ = 0;                                   // of the last decoded chunk
  std::vector<std::uint16_t> line_;                      // its lines (2-byte samples or halves of 4-byte ones)
  std::vector<unsigned char> inflated_;                  // one chunk, before its byte order is undone
};

}  // namespace eyestream::io
