#include "glare/uniform_field.hpp"

#include <algorithm>

namespace eyestream::glare {

bool is_uniform_field(const cv::Mat& rgb, double surround, double tolerance) {
  CV_Assert(rgb.type() == CV_32FC3);
  // One sweep that stops at the first pixel proving the field is not
  // uniform. Two cheaper proofs first, which give the same answer: the
  // first pixel against the surround (the test at the end lets no channel
  // of a uniform field lie beyond a factor spread^2 of it; spread^3 here,
  // a margin far above rounding), and the middle
  // row (a scene whose top rows are an even sky differs there sooner).
  const double spread = 1.0 + tolerance;
  if (rgb.rows == 0 || rgb.cols == 0) return surround == 0.0;  // (the empty range: lo = hi = 0)
  const cv::Vec3f first = rgb.at<cv::Vec3f>(0, 0);
  const double wide = spread * spread * spread;
  for (int c = 0; c < 3; ++c)
    if (!(surround * wide >= first[c] && surround <= first[c] * wide)) return false;
  double lo[3], hi[3];
  for (int c = 0; c < 3; ++c) lo[c] = hi[c] = first[c];
  const auto sweep_row = [&](int y) {
    const cv::Vec3f* p = rgb.ptr<cv::Vec3f>(y);
    for (int x = 0; x < rgb.cols; ++x)
      for (int c = 0; c < 3; ++c) {
        const double v = p[x][c];
        if (!(v >= 0.0)) return false;  // negative or NaN
        lo[c] = std::min(lo[c], v);
        hi[c] = std::max(hi[c], v);
        if (hi[c] > spread * lo[c]) return false;
      }
    return true;
  };
  if (!sweep_row(rgb.rows / 2)) return false;
  for (int y = 0; y < rgb.rows; ++y)
    if (!sweep_row(y)) return false;
  // The surround is grey: every channel must match it too, or a coloured
  // field would take the surround's colour at its edges.
  for (int c = 0; c < 3; ++c)
    if (!(surround >= lo[c] / spread && surround <= hi[c] * spread)) return false;  // a NaN surround too
  return true;
}

}  // namespace eyestream::glare
