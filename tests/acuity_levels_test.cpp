// The blur levels of the acuity loss (retina/acuity_loss.hpp) against
// OpenCV's GaussianBlur: a pixel whose first kept band is k takes the image
// blurred by sigma_(k-1), whether or not the finer levels between were
// made (a level no pixel takes is skipped and the next blur supplies its
// variance), and pixels that keep every band are left as they were.
#include <gtest/gtest.h>

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

TEST(AcuityLevels, APixelAtBandKTakesTheImageBlurredBySigmaKMinusOne) {
  AcuityParams p;  // every level at full resolution
  const AcuityLoss loss(p, 64.0, 1);
  const cv::Size size(160, 96);
  cv::Mat image(size, CV_32FC3);
  cv::randu(image, 0.0, 1.0);
  int tested = 0;
  for (int k : {1, 2, 3, 4, 5}) {
    if (!(loss.thresholds()[size_t(k)] < loss.thresholds()[size_t(k - 1)])) continue;  // bands sharing a threshold
    ++tested;
    cv::Mat out = image.clone();
    loss.apply(out, halves_map(loss, size, k));
    const double sigma = loss.sigmas_px()[size_t(k - 1)];
    cv::Mat want;
    if (sigma >= 0.19)
      cv::GaussianBlur(image, want, cv::Size(0, 0), sigma, sigma, cv::BORDER_REPLICATE);
    else
      want = image.clone();  // a blur under 0.19 px is a copy (acuity_loss.cpp)
    const cv::Rect left(0, 0, size.width / 2, size.height), right(size.width / 2, 0, size.width / 2, size.height);
    EXPECT_LT(cv::norm(out(left), want(left), cv::NORM_INF), 2e-6) << "k " << k << ", sigma " << sigma;
    EXPECT_EQ(cv::norm(out(right), image(right), cv::NORM_INF), 0.0) << "k " << k;
  }
  EXPECT_GE(tested, 3) << "bands 3 to 5 have thresholds of their own at 64 px/deg";
}

}  // namespace
}  // namespace eyestream::retina
