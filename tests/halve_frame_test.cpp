// halve_frame (retina/halve_frame.hpp) against OpenCV's cv::resize with
// INTER_AREA, bit for bit: three channels at even sizes (made here), odd
// sizes and one channel (OpenCV's), a region of a larger image, values
// from 1e-9 to 1e9 cd/m^2 in one image, a block of -0, an infinity and a
// NaN.
#include "retina/halve_frame.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <opencv2/imgproc.hpp>

namespace eyestream::retina {
namespace {

TEST(HalveFrame, IsCvResizesAreaMeanBitForBit) {
  cv::RNG random(3);
  for (const int type : {CV_32FC3, CV_32FC1})
    for (const cv::Size size :
         {cv::Size(64, 36), cv::Size(194, 110), cv::Size(65, 37), cv::Size(64, 37), cv::Size(2, 2)}) {
      cv::Mat big(size.height + 3, size.width + 5, type);
      random.fill(big, cv::RNG::UNIFORM, 0.0, 1e5);
      big.ptr<float>(1)[3] = 1e9f;
      big.ptr<float>(1)[4] = 1e-9f;
      big.ptr<float>(2)[3] = 0.0f;
      // The first output pixel's block all -0 (OpenCV's sum starts at +0),
      // an infinity and a NaN elsewhere.
      for (int y = 1; y <= 2; ++y)
        for (int x = 2 * big.channels(); x < 4 * big.channels(); ++x) big.ptr<float>(y)[x] = -0.0f;
      big.ptr<float>(3)[2 * big.channels()] = INFINITY;
      big.ptr<float>(4)[7] = NAN;
      const cv::Mat frame = big(cv::Rect(cv::Point(2, 1), size));  // rows with gaps between them
      cv::Mat want, got;
      cv::resize(frame, want, cv::Size((size.width + 1) / 2, (size.height + 1) / 2), 0, 0, cv::INTER_AREA);
      halve_frame(frame, got);
      ASSERT_EQ(got.size(), want.size()) << size;
      ASSERT_EQ(got.type(), type);
      for (int y = 0; y < got.rows; ++y)
        EXPECT_EQ(std::memcmp(got.ptr(y), want.ptr(y), size_t(got.cols) * got.elemSize()), 0) << size << " row " << y;
      // An exactly sized image: a read or write past its last pixel is the
      // sanitizer build's error.
      cv::Mat exact;
      halve_frame(frame.clone(), exact);
      for (int y = 0; y < got.rows; ++y)
        EXPECT_EQ(std::memcmp(exact.ptr(y), want.ptr(y), size_t(got.cols) * got.elemSize()), 0)
            << size << " exactly sized, row " << y;
    }
}

}  // namespace
}  // namespace eyestream::retina
