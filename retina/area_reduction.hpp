// An image reduced by area means: what
// cv::resize with INTER_AREA gives for three-channel floats, bit for bit
// (on its general path, OpenCV's taps, weights and order of terms: each output row is the sum
// of its input rows' weighted row sums, each row sum the sum of its
// pixels' weighted values). OpenCV's loop adds one weighted value at a
// time through a table of taps, storing and reloading the sum each time;
// here a pixel's three sums stay in one vector register, and an input row
// shared by two output rows is summed once (for 1920 x 1080 to 595 x 335
// on one thread, about half OpenCV's time; vector gathers over the output
// values were slower than OpenCV on this project's AMD EPYC machine). For
// the retina stage's reduction of the frame to `balanced`'s grid (0.31
// site a pixel at 1080p). Whole factors each way, where OpenCV takes its
// other path (`fast`'s grid, a quarter of the frame each way), are made
// here too as that path makes them: each value the sum of its block's
// values, four at a time, times 1 / area. OpenCV makes one value at a
// time, here a pixel's three values as one vector: for 1920 x 1080 to
// 480 x 270 on one thread, 2.3-2.4 ms and 1.5-1.6 in turn in one program
// (docs/performance.md). Other types, enlargements and
// reductions not whole each way of 7 or more across (past the taps a
// pixel holds here) go to cv::resize itself. On the general path, one
// difference: OpenCV starts the first row of each of its row stripes at
// +0 + the first term, the others at the first term, so where that term
// is -0 (a negative row sum too small for a float) its output depends on
// its stripes; here it is the term, -0.
#pragma once

#include <array>
#include <optional>
#include <opencv2/core.hpp>
#include <vector>

namespace eyestream::retina {

class AreaReduction {
 public:
  AreaReduction(cv::Size from, cv::Size to);

  cv::Size from() const { return from_; }
  cv::Size to() const { return to_; }

  // out = `in` (from()-sized) reduced to to(). out must not be in.
  void apply(const cv::Mat& in, cv::Mat& out) const;
  // Whether apply() makes three-channel floats itself (else cv::resize
  // does).
  bool replaces_opencv() const { return path_ != Path::kOpenCv; }

 private:
  // One axis's taps: output index d takes input indices
  // first[d] .. first[d] + count[d] - 1 with weights weight[d][t].
  struct Axis {
    std::vector<int> first, count;
    std::vector<std::vector<float>> weight;
    Axis(int from, int to);
  };
  cv::Size from_, to_;
  // Who makes the reduction: cv::resize; here, by the taps below (a
  // factor not whole both ways); or here, by blocks of factor_ (whole
  // factors both ways, as OpenCV's other path does).
  enum class Path { kOpenCv, kGeneral, kWholeFactor };
  Path path_ = Path::kOpenCv;
  cv::Size factor_;
  // The row sums' taps: output pixel d sums n input pixels from first_[d]
  // with weights weight_[d * kMostTaps + t]. by_taps_[n] lists the pixels
  // with n taps, but those whose last tap is the row's last input pixel,
  // which last_[n] lists.
  static constexpr int kMostTaps = 8;
  std::vector<int> first_;
  std::vector<float> weight_;
  std::array<std::vector<int>, kMostTaps + 1> by_taps_, last_;
  std::optional<Axis> down_;  // the output rows' taps
};

}  // namespace eyestream::retina
