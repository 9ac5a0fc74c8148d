// A 128-bit digest of an image's size, type and bytes (XXH3, libxxhash),
// by which a stage recognises a frame it has seen without keeping a copy of
// it: the glare stage's still-scene cache held a whole frame (25 MB at
// 1080p) to compare the next one with. Two different frames share a digest
// with a chance of about 2^-128.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

namespace eyestream::pipeline {

struct FrameDigest {
  int rows = 0, cols = 0, type = -1;
  std::uint64_t low = 0, high = 0;
  bool operator==(const FrameDigest& o) const {
    return rows == o.rows && cols == o.cols && type == o.type && low == o.low && high == o.high;
  }
};

// The digest of `image`'s pixels row by row (padding between rows is not
// read): the same for equal images whatever their strides.
FrameDigest frame_digest(const cv::Mat& image);

}  // namespace eyestream::pipeline
