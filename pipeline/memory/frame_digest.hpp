// A 128-bit digest of an image's size, type and bytes (XXH3, libxxhash),
// by which a stage recognises a frame it has seen without keeping a copy of
// it: the glare stage's still-scene cache held a whole frame (25 MB at
// 1080p) to compare the next one with. Two different frames share a digest
// with a chance of about 2^-128.
//
// Each row is digested on its own and the frame's digest is that of the
// rows' digests in order: rows can be digested on any thread, or in a pass
// that reads them for something else (RowDigests), and give the same.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace eyestream::pipeline {

struct FrameDigest {
  int rows = 0, cols = 0, type = -1;
  std::uint64_t low = 0, high = 0;
  bool operator==(const FrameDigest& o) const {
    return rows == o.rows && cols == o.cols && type == o.type && low == o.low && high == o.high;
  }
};

// The rows' digests of one image, filled a row at a time (each row once,
// from any thread; padding between rows is not read).
class RowDigests {
 public:
  explicit RowDigests(const cv::Mat& image);
  void add_row(int y);
  FrameDigest digest() const;  // once every row is added

 private:
  cv::Mat image_;
  std::vector<std::uint64_t> rows_;  // two words a row
};

// The digest of `image`: the same for equal images whatever their strides.
FrameDigest frame_digest(const cv::Mat& image);

}  // namespace eyestream::pipeline
