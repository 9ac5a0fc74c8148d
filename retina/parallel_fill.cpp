#include "retina/parallel_fill.hpp"

namespace eyestream::retina {

cv::Mat filled_in_parallel(cv::Size size, int type, const cv::Scalar& value) {
  cv::Mat m(size, type);
  cv::parallel_for_(cv::Range(0, m.rows),
                    [&](const cv::Range& rows) { m.rowRange(rows.start, rows.end).setTo(value); });
  return m;
}

}  // namespace eyestream::retina
