#include "pipeline/memory/frame_digest.hpp"

#include <xxhash.h>

namespace eyestream::pipeline {

FrameDigest frame_digest(const cv::Mat& image) {
  CV_Assert(image.dims == 2);
  FrameDigest d;
  d.rows = image.rows;
  d.cols = image.cols;
  d.type = image.type();
  const size_t row_bytes = size_t(image.cols) * image.elemSize();
  XXH128_hash_t h;
  if (image.isContinuous()) {
    h = XXH3_128bits(image.data, row_bytes * size_t(image.rows));
  } else {
    // The streaming digest of the rows in order is the one-call digest of
    // their concatenation.
    XXH3_state_t* state = XXH3_createState();
    CV_Assert(state && XXH3_128bits_reset(state) == XXH_OK);
    for (int y = 0; y < image.rows; ++y) XXH3_128bits_update(state, image.ptr(y), row_bytes);
    h = XXH3_128bits_digest(state);
    XXH3_freeState(state);
  }
  d.low = h.low64;
  d.high = h.high64;
  return d;
}

}  // namespace eyestream::pipeline
