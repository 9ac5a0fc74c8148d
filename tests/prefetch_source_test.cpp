// The prefetching reader: frames arrive in order with their times, a frame
// that fails to read is reported at that frame, and the reader decodes a
// frame only when there is room for it, so it holds no more than `depth`
// frames that next() has not returned (each a whole frame of memory at
// 1080p), and none after the last one a run wants.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "io/error.hpp"
#include "io/prefetch_source.hpp"

namespace eyestream {
namespace {

// Frames 0..count-1 at 0.1 s intervals, made instantly; frame `bad` fails.
class CountingSource : public io::FrameSource {
 public:
  CountingSource(int count, int bad, std::atomic<int>& made) : count_(count), bad_(bad), made_(made) {
    info_.width = 4;
    info_.height = 2;
    info_.frames_per_second = 10.0;
    info_.frame_count = count;
  }
  const io::SourceInfo& info() const override { return info_; }
  std::optional<io::SceneFrame> next() override {
    if (next_ == count_) return std::nullopt;
    const int i = next_++;
    if (i == bad_) throw InputError("frame " + std::to_string(i) + " is bad");
    io::SceneFrame f;
    f.index = i;
    f.time_s = 0.1 * i;
    f.rgb = cv::Mat(2, 4, CV_32FC3, cv::Scalar::all(double(i)));
    ++made_;
    return f;
  }

 private:
  io::SourceInfo info_;
  int count_, bad_, next_ = 0;
  std::atomic<int>& made_;
};

// Waits (up to 10 s) until the reader has made `count` frames, then gives
// it time to run further ahead if it would; returns how many it made.
int made_after_waiting_for(const std::atomic<int>& made, int count) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (made.load() < count && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  return made.load();
}

TEST(PrefetchSource, HoldsNoMoreThanItsDepthOfFramesNotYetReturned) {
  std::atomic<int> made{0};
  io::PrefetchSource source(std::make_unique<CountingSource>(10, -1, made), 1);
  EXPECT_EQ(made_after_waiting_for(made, 1), 1) << "one frame queued, none decoded beyond it";
  const std::optional<io::SceneFrame> first = source.next();
  ASSERT_TRUE(first);
  EXPECT_EQ(first->index, 0);
  EXPECT_EQ(made_after_waiting_for(made, 2), 2) << "frame 0 returned, frame 1 queued, frame 2 not read yet";
}

TEST(PrefetchSource, GivesEveryFrameInOrderWithItsTime) {
  std::atomic<int> made{0};
  io::PrefetchSource source(std::make_unique<CountingSource>(6, -1, made), 1);
  for (int i = 0; i < 6; ++i) {
    const std::optional<io::SceneFrame> f = source.next();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->index, i);
    EXPECT_DOUBLE_EQ(f->time_s, 0.1 * i);
    EXPECT_EQ(f->rgb.at<cv::Vec3f>(1, 3)[2], float(i));
  }
  EXPECT_FALSE(source.next());
  EXPECT_FALSE(source.next()) << "still nothing after the end";
}

// A run to --end-frame: the reader decodes no frame after the last one the
// run takes (a 1080p frame's decoding and memory for nothing), and the
// source ends there.
TEST(PrefetchSource, DecodesNothingAfterTheLastIndex) {
  std::atomic<int> made{0};
  io::PrefetchSource source(std::make_unique<CountingSource>(10, -1, made), 1, 2);
  for (int i = 0; i < 3; ++i) {
    const std::optional<io::SceneFrame> f = source.next();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->index, i);
  }
  EXPECT_EQ(made_after_waiting_for(made, 3), 3) << "frame 3 would be past the last";
  EXPECT_FALSE(source.next());
  EXPECT_FALSE(source.next()) << "still nothing after the end";
  EXPECT_EQ(made.load(), 3);
}

TEST(PrefetchSource, AFrameThatFailsThrowsWhenItIsTaken) {
  std::atomic<int> made{0};
  io::PrefetchSource source(std::make_unique<CountingSource>(6, 2, made), 1);
  ASSERT_TRUE(source.next());
  ASSERT_TRUE(source.next());
  try {
    source.next();
    FAIL() << "frame 2 should throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("frame 2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace eyestream
