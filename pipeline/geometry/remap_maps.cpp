#include "pipeline/geometry/remap_maps.hpp"

#include <opencv2/imgproc.hpp>

namespace eyestream::pipeline {

void remap_maps(const cv::Mat& positions, cv::Mat& map1, cv::Mat& map2) {
  CV_Assert(positions.type() == CV_32FC2);
  map1.create(positions.size(), CV_16SC2);
  map2.create(positions.size(), CV_16UC1);
  // OpenCV's arithmetic: the shift in float (as Mat - Scalar on a float
  // image), each coordinate times INTER_TAB_SIZE rounded to the nearest
  // (even on a tie: cvRound), its whole part by an arithmetic shift and
  // its fraction as the table's index. Every pixel on its own: rows in
  // parallel give the same values whatever the split.
  constexpr int kTab = cv::INTER_TAB_SIZE;
  cv::parallel_for_(cv::Range(0, positions.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const cv::Vec2f* p = positions.ptr<cv::Vec2f>(y);
      short* whole = map1.ptr<short>(y);
      ushort* fraction = map2.ptr<ushort>(y);
      for (int x = 0; x < positions.cols; ++x) {
        const int ix = cvRound((p[x][0] - 0.5f) * float(kTab)), iy = cvRound((p[x][1] - 0.5f) * float(kTab));
        whole[2 * x] = cv::saturate_cast<short>(ix >> cv::INTER_BITS);
        whole[2 * x + 1] = cv::saturate_cast<short>(iy >> cv::INTER_BITS);
        fraction[x] = ushort((iy & (kTab - 1)) * kTab + (ix & (kTab - 1)));
      }
    }
  });
}

}  // namespace eyestream::pipeline
