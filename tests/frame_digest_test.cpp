// The frame digest (pipeline/memory/frame_digest.hpp) against XXH3's plain
// entry point called here on each row of a packed copy of the pixels and then on the rows'
// digests: the same for a region of a larger image (rows with gaps between
// them) and when made a row at a time in any order, different for one
// changed byte, a changed shape of the same bytes, or another type.
#include <gtest/gtest.h>

#include <xxhash.h>

#include <vector>

#include "pipeline/memory/frame_digest.hpp"

namespace eyestream::pipeline {
namespace {

TEST(FrameDigest, IsXxh3OfTheRowsXxh3sAndSeesOneByte) {
  // Rows of 23 KB (22 of XXH3's 1 KB blocks of its long-input loop, as a
  // 1080p frame's): the digest uses the library's dispatch to its widest
  // vector code, the plain entry point here its SSE2 code.
  cv::Mat big(40, 1990, CV_32FC3);
  cv::randu(big, 0.0, 1.0);
  const cv::Mat region = big(cv::Rect(5, 3, 1930, 20));
  ASSERT_FALSE(region.isContinuous());
  const cv::Mat packed = region.clone();
  std::vector<std::uint64_t> row_words;
  for (int y = 0; y < packed.rows; ++y) {
    const XXH128_hash_t row = XXH3_128bits(packed.ptr(y), size_t(packed.cols) * packed.elemSize());
    row_words.push_back(row.low64);
    row_words.push_back(row.high64);
  }
  const XXH128_hash_t want = XXH3_128bits(row_words.data(), row_words.size() * sizeof(std::uint64_t));
  const FrameDigest d = frame_digest(region);
  EXPECT_EQ(d.low, want.low64);
  EXPECT_EQ(d.high, want.high64);
  RowDigests backwards(region);  // rows added in another order, as threads may
  for (int y = region.rows - 1; y >= 0; --y) backwards.add_row(y);
  EXPECT_TRUE(d == backwards.digest());
  EXPECT_TRUE(d == frame_digest(packed));
  cv::Mat changed = packed.clone();
  changed.data[1234] ^= 1;
  EXPECT_FALSE(d == frame_digest(changed));
  EXPECT_FALSE(d == frame_digest(packed.reshape(3, 1930)));  // the same bytes, 1930 rows of 20
  cv::Mat as_ints(packed.size(), CV_32SC3, packed.data);
  EXPECT_FALSE(d == frame_digest(as_ints));
}

}  // namespace
}  // namespace eyestream::pipeline
