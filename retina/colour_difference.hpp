// Colour difference for comparing outputs: CIELAB from display-linear
// Rec.709 and the CIEDE2000 difference (Sharma, Wu and Dalal 2005, "The
// CIEDE2000 color-difference formula: implementation notes"; CIE 142:2001).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace eyestream::retina {

// CIELAB (L*, a*, b*) of a linear Rec.709 colour relative to a display white
// of 1 (D65 white point, IEC 61966-2-1 matrix).
cv::Vec3d lab_from_linear_rec709(const cv::Vec3f& rgb);

// CIEDE2000 Delta E_00 between two CIELAB colours (k_L = k_C = k_H = 1).
double ciede2000(const cv::Vec3d& lab1, const cv::Vec3d& lab2);

// Per-pixel CIEDE2000 (CV_32F) of two same-sized CV_32FC3 frames of
// display values relative to white: linear when decode_gamma is 1, else
// code values in [0, 1] decoded as v^decode_gamma. Rows run in parallel and
// each pixel is written once: the result does not depend on threads.
cv::Mat ciede2000_map(const cv::Mat& a, const cv::Mat& b, double decode_gamma);

// CIEDE2000 values gathered over many frames in bins of 0.01 up to 100, for
// percentiles over whole sequences in constant memory.
class DeltaEHistogram {
 public:
  static constexpr double kStep = 0.01;
  void add(const cv::Mat& de);  // a CV_32F map
  // The q-quantile (0 < q <= 1), rounded down to the bin; 0 when empty.
  double quantile(double q) const;
  double max() const { return max_; }
  std::uint64_t count() const { return count_; }

 private:
  std::vector<std::uint64_t> bins_ = std::vector<std::uint64_t>(size_t(100.0 / kStep) + 1, 0);
  std::uint64_t count_ = 0;
  double max_ = 0.0;
};

}  // namespace eyestream::retina
