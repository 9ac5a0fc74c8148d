// zlib's one-call `uncompress`, done by libdeflate, for the OpenEXR library.
//
// OpenEXR 3.1 (Debian 12's) inflates every ZIP and ZIPS block of an EXR
// through zlib's `uncompress`: 20 ms of CPU a 1080p frame of the night
// city, a tenth of a `fast` run's. libdeflate, a Debian package made for
// whole buffers, inflates the same blocks in 2 ms (docs/performance.md).
// The OpenEXR libraries ask for `uncompress` without a symbol version, so
// the program's own definition, exported (CMakeLists.txt), is the one the
// dynamic linker binds them to. It keeps zlib's contract where callers
// rely on it: the same bytes, *dest_length set to their count, Z_OK;
// Z_BUF_ERROR when `dest` is too small; Z_DATA_ERROR for corrupt or
// incomplete data; Z_MEM_ERROR when no decompressor can be made. On an
// error *dest_length is 0 (zlib gives the count of the bytes it wrote
// before the error; no caller here reads them).
// tests/zlib_uncompress_test.cpp holds it to zlib's own function on
// zlib's streams at three levels and on four kinds of fault.
#include <libdeflate.h>
#include <zlib.h>

#include <memory>

namespace {

struct FreeDecompressor {
  void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};

// One per thread: OpenEXR inflates blocks on its pool's threads at once.
// Made on first use, and again after a failure to make it.
libdeflate_decompressor* thread_decompressor() noexcept {
  thread_local std::unique_ptr<libdeflate_decompressor, FreeDecompressor> d;
  if (!d) d.reset(libdeflate_alloc_decompressor());
  return d.get();
}

}  // namespace

extern "C" int uncompress(Bytef* dest, uLongf* dest_length, const Bytef* source, uLong source_length) {
  libdeflate_decompressor* d = thread_decompressor();
  if (!d) {
    *dest_length = 0;
    return Z_MEM_ERROR;
  }
  size_t in_used = 0, out_used = 0;
  // Data after the stream's end is ignored, as zlib does.
  const libdeflate_result r =
      libdeflate_zlib_decompress_ex(d, source, source_length, dest, *dest_length, &in_used, &out_used);
  switch (r) {
    case LIBDEFLATE_SUCCESS:
      *dest_length = uLongf(out_used);
      return Z_OK;
    case LIBDEFLATE_INSUFFICIENT_SPACE:
      *dest_length = 0;
      return Z_BUF_ERROR;
    default:
      *dest_length = 0;
      return Z_DATA_ERROR;
  }
}
