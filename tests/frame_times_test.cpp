// Sources that know their frames' times without decoding them (file
// sequences): time_of(i) is the time next() gives frame i, (number_i -
// number_0) / fps computed here from the file numbers, also across a gap
// in the numbering; nothing past the end; and the prefetching reader
// answers for the source it wraps, whatever frames it has decoded. The
// run loop relies on it to hold two decoded frames instead of three.
#include <gtest/gtest.h>

#include "io/exr_file.hpp"
#include "io/exr_sequence_source.hpp"
#include "io/prefetch_source.hpp"
#include "tests/test_support.hpp"

namespace eyestream::io {
namespace {

TEST(FrameTimes, AnExrSequenceKnowsThemFromItsFileNumbersAcrossAGap) {
  test::ScratchDir dir;
  const int numbers[] = {3, 4, 7, 8};  // 5 and 6 missing
  for (int n : numbers)
    write_exr(dir / ("f_" + std::to_string(n) + ".exr"), test::constant_frame(4, 4, {1, 1, 1}),
              {true, std::nullopt, 24.0});
  ExrSequenceOptions o;
  o.skip_missing = true;
  ExrSequenceSource source(dir / "f_%d.exr", o);
  ASSERT_TRUE(source.knows_times());
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(source.time_of(i).has_value()) << i;
    EXPECT_DOUBLE_EQ(*source.time_of(i), (numbers[i] - 3) / 24.0) << i;
    const std::optional<SceneFrame> f = source.next();
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->index, i);
    EXPECT_DOUBLE_EQ(f->time_s, *source.time_of(i));
  }
  EXPECT_FALSE(source.time_of(4).has_value());
  EXPECT_FALSE(source.next().has_value());
}

TEST(FrameTimes, ThePrefetchingReaderAnswersForItsSource) {
  test::ScratchDir dir;
  for (int n = 0; n < 5; ++n)
    write_exr(dir / ("g_" + std::to_string(n) + ".exr"), test::constant_frame(4, 4, {1, 1, 1}),
              {true, std::nullopt, 30.0});
  PrefetchSource source(std::make_unique<ExrSequenceSource>(dir / "g_%d.exr", ExrSequenceOptions{}), 1);
  ASSERT_TRUE(source.knows_times());
  for (int i = 0; i < 5; ++i) {
    const std::optional<SceneFrame> f = source.next();
    ASSERT_TRUE(f.has_value());
    EXPECT_DOUBLE_EQ(*source.time_of(i), f->time_s);
    if (i + 1 < 5) {
      EXPECT_DOUBLE_EQ(*source.time_of(i + 1), (i + 1) / 30.0) << "known before it is taken";
    }
  }
  EXPECT_FALSE(source.time_of(5).has_value());
}

}  // namespace
}  // namespace eyestream::io
