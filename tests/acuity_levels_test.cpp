// The blur levels of the acuity loss (retina/acuity_loss.hpp) against
// OpenCV's GaussianBlur: a pixel whose first kept band is k takes the image
// blurred to sigma_(k-1): the first level a pixel can take is one blur of
// the image (the finer ones, whose bands share a threshold with it, are not
// made), each deeper one the last blurred by the variance it lacks; pixels that keep every band are left as they
// were. With the next level's pixels beside them, under the presets'
// reduced levels too, each pixel's level is the same: what a level holds
// does not depend on which others the frame takes. A level map held
// reduced acts as its enlargement, which is cv::resize's bilinear one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include <opencv2/imgproc.hpp>

#include "retina/acuity_loss.hpp"

namespace eyestream::retina {
namespace {

// A level map putting the left half of the image between tau_k and
// tau_(k-1) (band k - 1 lost, band k kept, unless they share a threshold)
// and the right half above every threshold (nothing lost).
cv::Mat halves_map(const AcuityLoss& loss, cv::Size size, int k) {
  const std::vector<double>& tau = loss.thresholds();
  cv::Mat level(size, CV_32F, cv::Scalar(float(tau.front() + 1.0)));
  level(cv::Rect(0, 0, size.width / 2, size.height)) = float(0.5 * (tau[size_t(k - 1)] + tau[size_t(k)]));
  return level;
}

// A level between tau_(k-1) and tau_k (band k - 1 lost, band k kept);
// for k = 0, above every threshold (nothing lost).
float band_level(const AcuityLoss& loss, int k) {
  const std::vector<double>& tau = loss.thresholds();
  return k == 0 ? float(tau.front() + 1.0) : float(0.5 * (tau[size_t(k - 1)] + tau[size_t(k)]));
}

cv::Mat random_image(cv::Size size) {
  cv::Mat image(size, CV_32FC3);
  cv::randu(image, 0.0, 1.0);
  return image;
}

// Levels held at full resolution (0), as in `fast` (1.2) and `balanced`
// (2.5), and with the deepest alone reduced (3.0), at 64 px/deg.
constexpr double kPyramids[] = {0.0, 1.2, 2.5, 3.0};

AcuityLoss loss_with_pyramid(double pyramid) {
  AcuityParams p;
  p.pyramid_from_px = pyramid;
  return AcuityLoss(p, 64.0, 1);
}

// Full-resolution level k (from 3, the first a pixel can take at 64
// px/deg) made by OpenCV: one blur of the image by its sigma, each deeper
// one the last blurred by what its variance lacks.
cv::Mat opencv_level(const cv::Mat& image, const AcuityLoss& loss, int k) {
  const std::vector<double>& sigma = loss.sigmas_px();
  const int first_takeable = 3;
  cv::Mat want;
  cv::GaussianBlur(image, want, cv::Size(0, 0), sigma[size_t(first_takeable - 1)], sigma[size_t(first_takeable - 1)],
                   cv::BORDER_REPLICATE);
  for (int j = first_takeable; j < k; ++j) {
    const double extra = std::sqrt(sigma[size_t(j)] * sigma[size_t(j)] - sigma[size_t(j - 1)] * sigma[size_t(j - 1)]);
    cv::GaussianBlur(want, want, cv::Size(0, 0), extra, extra, cv::BORDER_REPLICATE);
  }
  return want;
}

TEST(AcuityLevels, APixelAtBandKTakesTheImageBlurredToSigmaKMinusOne) {
  AcuityParams p;  // every level at full resolution
  const AcuityLoss loss(p, 64.0, 1);
  const cv::Size size(160, 96);
  cv::Mat image(size, CV_32FC3);
  cv::randu(image, 0.0, 1.0);
  ASSERT_EQ(loss.thresholds()[0], loss.thresholds()[2]);  // bands 0 to 2 share a threshold at 64 px/deg
  ASSERT_LT(loss.thresholds()[3], loss.thresholds()[2]);
  for (int k : {3, 4, 5}) {
    cv::Mat out = image.clone();
    loss.apply(out, halves_map(loss, size, k));
    const cv::Mat want = opencv_level(image, loss, k);
    const cv::Rect left(0, 0, size.width / 2, size.height), right(size.width / 2, 0, size.width / 2, size.height);
    EXPECT_LT(cv::norm(out(left), want(left), cv::NORM_INF), 2e-6) << "k " << k;
    EXPECT_EQ(cv::norm(out(right), image(right), cv::NORM_INF), 0.0) << "k " << k;
  }
}

TEST(AcuityLevels, ALevelIsTheSameWhicheverOthersTheFrameTakes) {
  // Thirds at bands 3, 4 and 5 (levels chained and, under fast and
  // balanced, held reduced) against each band alone over the whole image.
  const cv::Size size(192, 96);
  const cv::Mat image = random_image(size);
  for (double pyramid : kPyramids) {
    const AcuityLoss loss = loss_with_pyramid(pyramid);
    cv::Mat mixed_level(size, CV_32F);
    cv::Mat mixed = image.clone();
    for (int third = 0; third < 3; ++third) mixed_level(cv::Rect(third * 64, 0, 64, size.height)) = band_level(loss, 3 + third);
    loss.apply(mixed, mixed_level);
    for (int third = 0; third < 3; ++third) {
      const int k = 3 + third;
      cv::Mat alone = image.clone();
      loss.apply(alone, cv::Mat(size, CV_32F, cv::Scalar(band_level(loss, k))));
      const cv::Rect r(third * 64, 0, 64, size.height);
      EXPECT_EQ(cv::norm(mixed(r), alone(r), cv::NORM_INF), 0.0) << "band " << k << ", pyramid " << pyramid;
    }
  }
}

TEST(AcuityLevels, EveryPixelOfAMosaicTakesItsOwnLevel) {
  // Runs of 1 to 19 pixels, each of one level (bands 3 to 6 or nothing
  // lost), starting anywhere against 8-byte boundaries, the last run of a
  // row cut by its end (offsets from a seeded draw): each pixel as its
  // level alone over the whole image makes it, bit for bit, and a pixel
  // that keeps every band as it was; at full resolution each level alone
  // within 2e-6 of OpenCV's blurs.
  const cv::Size size(203, 41);
  const cv::Mat image = random_image(size);
  for (double pyramid : kPyramids) {
    const AcuityLoss loss = loss_with_pyramid(pyramid);
    const int bands[] = {0, 3, 4, 5, 6};
    cv::Mat band(size, CV_8U), level(size, CV_32F);
    cv::RNG rng(7);
    for (int y = 0; y < size.height; ++y)
      for (int x = 0; x < size.width;) {
        const int k = bands[rng.uniform(0, 5)], n = rng.uniform(1, 20);
        for (int e = std::min(x + n, size.width); x < e; ++x) {
          band.at<std::uint8_t>(y, x) = std::uint8_t(k);
          level.at<float>(y, x) = band_level(loss, k);
        }
      }
    cv::Mat mosaic = image.clone();
    loss.apply(mosaic, level);
    for (int k : bands) {
      cv::Mat alone = image.clone();
      loss.apply(alone, cv::Mat(size, CV_32F, cv::Scalar(band_level(loss, k))));
      int differing = 0, pixels = 0;
      for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x)
          if (band.at<std::uint8_t>(y, x) == k) {
            ++pixels;
            differing += std::memcmp(&mosaic.at<cv::Vec3f>(y, x), &alone.at<cv::Vec3f>(y, x), sizeof(cv::Vec3f)) != 0;
          }
      EXPECT_GT(pixels, 1000) << "band " << k;
      EXPECT_EQ(differing, 0) << "band " << k << ", pyramid " << pyramid;
      if (k > 0) {
        EXPECT_GT(cv::norm(alone, image, cv::NORM_INF), 0.01) << "band " << k;  // a blur, not the image
      }
      if (k > 0 && pyramid == 0.0) {  // and at full resolution, OpenCV's blurs
        EXPECT_LT(cv::norm(alone, opencv_level(image, loss, k), cv::NORM_INF), 2e-6) << "band " << k;
      }
    }
  }
}

TEST(AcuityLevels, AReducedLevelMapActsAsItsEnlargementWhichIsCvResizes) {
  // A frame not a whole number of reduced pixels each way (203 / 51, 117 /
  // 30), a map crossing several thresholds in both directions.
  const cv::Size size(203, 117), reduced(51, 30);
  AcuityParams p;
  p.pyramid_from_px = 1.5;
  const AcuityLoss loss(p, 64.0, 1);
  const std::vector<double>& tau = loss.thresholds();
  cv::Mat level(reduced, CV_32F);
  for (int y = 0; y < reduced.height; ++y)
    for (int x = 0; x < reduced.width; ++x)
      level.at<float>(y, x) = float(tau.back() - 0.2 + (tau.front() - tau.back() + 0.4) *
                                                            (0.5 + 0.5 * std::sin(0.3 * x) * std::cos(0.2 * y)));
  // The enlargement: OpenCV's bilinear resize, to float rounding (its
  // passes run in the other order).
  const cv::Mat enlarged = enlarged_level(level, size);
  cv::Mat want;
  cv::resize(level, want, size, 0, 0, cv::INTER_LINEAR);
  EXPECT_LT(cv::norm(enlarged, want, cv::NORM_INF), 1e-5);
  cv::Mat image(size, CV_32FC3);
  cv::randu(image, 0.0, 1.0);
  cv::Mat from_reduced = image.clone(), from_enlarged = image.clone();
  loss.apply(from_reduced, level);
  loss.apply(from_enlarged, enlarged);
  EXPECT_EQ(cv::norm(from_reduced, from_enlarged, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(from_reduced, image, cv::NORM_INF), 0.01);  // the loss blurred something
}

}  // namespace
}  // namespace eyestream::retina
