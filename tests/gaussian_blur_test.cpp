// The parallel Gaussian blur against OpenCV's GaussianBlur (an independent
// implementation of the same kernel and border) and a direct sum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <opencv2/imgproc.hpp>

#include "retina/gaussian_blur.hpp"

namespace eyestream::retina {
namespace {

cv::Mat random_image(int rows, int cols, int type, int seed) {
  cv::Mat m(rows, cols, type);
  cv::RNG rng{uint64_t(seed)};
  rng.fill(m, cv::RNG::UNIFORM, 0.0, 100.0);
  return m;
}

TEST(GaussianBlur, MatchesOpenCvWithReplicatedBorders) {
  for (const int type : {CV_32FC1, CV_32FC3})
    for (const double sigma : {0.2, 0.73, 1.5, 4.0, 11.0})
      for (const cv::Size size : {cv::Size(97, 61), cv::Size(7, 40), cv::Size(40, 3)}) {
        const cv::Mat src = random_image(size.height, size.width, type, int(sigma * 10));
        cv::Mat ours, theirs;
        gaussian_blur(src, ours, sigma);
        cv::GaussianBlur(src, theirs, cv::Size(0, 0), sigma, sigma, cv::BORDER_REPLICATE);
        const double worst = cv::norm(ours, theirs, cv::NORM_INF);
        EXPECT_LT(worst, 1e-3) << "sigma " << sigma << " size " << size << " channels " << CV_MAT_CN(type);
      }
}

TEST(GaussianBlur, IsTheDirectSumAtAPixel) {
  // out(x, y) = sum_ij g(i) g(j) src(clamp(x + i), clamp(y + j)), the
  // normalised sampled Gaussian of radius round(4 sigma).
  const double sigma = 2.3;
  const cv::Mat src = random_image(30, 50, CV_32FC1, 7);
  cv::Mat out;
  gaussian_blur(src, out, sigma);
  const int r = (int(std::lround(sigma * 8 + 1)) | 1) / 2;
  std::vector<double> g(size_t(2 * r + 1));
  double sum = 0.0;
  for (int i = -r; i <= r; ++i) sum += g[size_t(i + r)] = std::exp(-i * i / (2 * sigma * sigma));
  for (const cv::Point p : {cv::Point(0, 0), cv::Point(25, 15), cv::Point(49, 2)}) {
    double expected = 0.0;
    for (int j = -r; j <= r; ++j)
      for (int i = -r; i <= r; ++i)
        expected += g[size_t(i + r)] * g[size_t(j + r)] / (sum * sum) *
                    src.at<float>(std::clamp(p.y + j, 0, src.rows - 1), std::clamp(p.x + i, 0, src.cols - 1));
    EXPECT_NEAR(out.at<float>(p), expected, 1e-3 * std::abs(expected)) << p;
  }
}

// The blur's sums as their definition, a float at a time: the row sweep
// w0 c + w1 (l1 + r1) + w2 (l2 + r2) ... (terms in that order, borders
// replicated), then the same down the swept rows; the weights are OpenCV's
// float kernel's, as the blur's.
cv::Mat blur_by_definition(const cv::Mat& src, double sigma) {
  const int ksize = cvRound(sigma * 8 + 1) | 1, r = ksize / 2, ch = src.channels();
  const cv::Mat k = cv::getGaussianKernel(ksize, sigma, CV_64F);
  std::vector<float> w(size_t(r) + 1);
  for (int t = 0; t <= r; ++t) w[size_t(t)] = float(k.at<double>(r + t));
  cv::Mat across(src.size(), src.type()), out(src.size(), src.type());
  for (int y = 0; y < src.rows; ++y)
    for (int x = 0; x < src.cols; ++x)
      for (int c = 0; c < ch; ++c) {
        const float* row = src.ptr<float>(y);
        float sum = w[0] * row[x * ch + c];
        for (int t = 1; t <= r; ++t)
          sum += w[size_t(t)] * (row[std::max(x - t, 0) * ch + c] + row[std::min(x + t, src.cols - 1) * ch + c]);
        across.ptr<float>(y)[x * ch + c] = sum;
      }
  for (int y = 0; y < src.rows; ++y)
    for (int i = 0; i < src.cols * ch; ++i) {
      float sum = w[0] * across.ptr<float>(y)[i];
      for (int t = 1; t <= r; ++t)
        sum += w[size_t(t)] *
               (across.ptr<float>(std::max(y - t, 0))[i] + across.ptr<float>(std::min(y + t, src.rows - 1))[i]);
      out.ptr<float>(y)[i] = sum;
    }
  return out;
}

TEST(GaussianBlur, IsItsDefinitionBitForBit) {
  // Rows shorter and longer than the sweeps' blocks of 32 samples, around
  // the kernel's reach, with 1 to 4 channels: every sample's bits.
  for (const double sigma : {0.6, 2.5})
    for (int ch = 1; ch <= 4; ++ch) {
      const int r = (cvRound(sigma * 8 + 1) | 1) / 2;
      for (const int width : {1, 7, 31, 32, 33, 2 * r + 32 / ch, 2 * r + 65, 150}) {
        const cv::Mat src = random_image(2 * r + 9, width, CV_32FC(ch), width + ch);
        cv::Mat ours;
        gaussian_blur(src, ours, sigma);
        const cv::Mat want = blur_by_definition(src, sigma);
        EXPECT_EQ(std::memcmp(ours.data, want.data, want.total() * want.elemSize()), 0)
            << "sigma " << sigma << ", " << ch << " channels, width " << width;
      }
    }
}

TEST(GaussianBlur, InPlaceAndAnyThreadCountGiveTheSameBytes) {
  const cv::Mat src = random_image(200, 123, CV_32FC3, 3);
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  cv::Mat one;
  gaussian_blur(src, one, 1.7);
  cv::setNumThreads(threads > 1 ? threads : 2);
  cv::Mat many = src.clone();
  gaussian_blur(many, many, 1.7);
  cv::setNumThreads(threads);
  EXPECT_EQ(cv::norm(one, many, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace eyestream::retina
