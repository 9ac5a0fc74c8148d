#include "pipeline/memory/frame_digest.hpp"

#include <xxhash.h>

namespace eyestream::pipeline {

RowDigests::RowDigests(const cv::Mat& image) : image_(image), rows_(size_t(image.rows) * 2, 0) {
  CV_Assert(image.dims == 2);
}

void RowDigests::add_row(int y) {
  const XXH128_hash_t h = XXH3_128bits(image_.ptr(y), size_t(image_.cols) * image_.elemSize());
  rows_[size_t(y) * 2] = h.low64;
  rows_[size_t(y) * 2 + 1] = h.high64;
}

FrameDigest RowDigests::digest() const {
  FrameDigest d;
  d.rows = image_.rows;
  d.cols = image_.cols;
  d.type = image_.type();
  const XXH128_hash_t h = XXH3_128bits(rows_.data(), rows_.size() * sizeof(std::uint64_t));
  d.low = h.low64;
  d.high = h.high64;
  return d;
}

FrameDigest frame_digest(const cv::Mat& image) {
  RowDigests rows(image);
  cv::parallel_for_(cv::Range(0, image.rows), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y) rows.add_row(y);
  });
  return rows.digest();
}

}  // namespace eyestream::pipeline
