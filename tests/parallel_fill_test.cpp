// An image filled by rows in parallel (retina/parallel_fill.hpp) holds
// what cv::Mat's own fill gives, at every size and type the set-up uses.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "retina/parallel_fill.hpp"

namespace eyestream::retina {
namespace {

TEST(ParallelFill, GivesTheBytesOfCvMatsFill) {
  const cv::Scalar values[] = {cv::Scalar::all(0.0), cv::Scalar::all(1.0), cv::Scalar(0.25, -3.5, 7.0)};
  for (const cv::Size size : {cv::Size(1, 1), cv::Size(961, 1), cv::Size(3, 541), cv::Size(1920, 1080)})
    for (const int type : {CV_32F, CV_32FC3, CV_64FC3})
      for (const cv::Scalar& value : values) {
        const cv::Mat want(size, type, value);
        const cv::Mat got = filled_in_parallel(size, type, value);
        ASSERT_EQ(got.size(), size);
        ASSERT_EQ(got.type(), type);
        EXPECT_EQ(cv::norm(got, want, cv::NORM_INF), 0.0) << size << " type " << type << " value " << value;
      }
}

}  // namespace
}  // namespace eyestream::retina
