#include "pipeline/eye/grey_map.hpp"

namespace eyestream::pipeline {

cv::Mat one_channel_if_grey(const cv::Mat& map) {
  CV_Assert(map.type() == CV_32FC3);
  for (int y = 0; y < map.rows; ++y) {
    const cv::Vec3f* p = map.ptr<cv::Vec3f>(y);
    for (int x = 0; x < map.cols; ++x)
      if (!(p[x][0] == p[x][1] && p[x][0] == p[x][2])) return map;
  }
  cv::Mat grey(map.size(), CV_32F);
  cv::extractChannel(map, grey, 0);
  return grey;
}

}  // namespace eyestream::pipeline
