// The tone map's row loops (retina/tone_map.cpp: luminances, the power
// table a row at a time, colour) against the tone map's definition written
// out here pixel by pixel with ToneCurve::response and OpenCV's vector
// types: the same bits, photopic and mesopic, with a rho map, the hue shift
// on and off, and pixels that must come out black.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "retina/luminance.hpp"
#include "retina/tone_map.hpp"

namespace eyestream::retina {
namespace {

cv::Vec3f defined(const cv::Vec3f& p, const ToneCurve& curve, const MesopicColour& m, float rho) {
  const cv::Vec3f tint = (m.hue_shift ? m.tint_ratio : cv::Vec3f(0, 0, 0)) * (1.0f - rho);
  const float share = m.hue_shift ? rho : 1.0f;
  const float yp = photopic_luminance(p);
  const float ys = m.scotopic_weights.dot(p);
  const float ym = rho * yp + (1.0f - rho) * ys;
  if (!(yp > 0.0f) || !(ym > 0.0f) || !std::isfinite(ym)) return cv::Vec3f(0, 0, 0);
  const float r = curve.response(ym);
  return p * (share * r / yp) + tint * r;
}

// Luminances from 1e-9 to 1e9 cd/m^2 in random colours, with zeros,
// negatives, NaN, infinities and denormals among them.
cv::Mat frame(cv::Size size) {
  cv::Mat f(size, CV_32FC3);
  cv::RNG rng(7);
  const float odd[] = {0.0f, -0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(),
                       std::numeric_limits<float>::infinity(), 1e-42f, 3e38f};
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      const float l = std::pow(10.0f, float(rng.uniform(-9.0, 9.0)));
      cv::Vec3f p(l * float(rng.uniform(0.0, 1.5)), l * float(rng.uniform(0.0, 1.5)), l * float(rng.uniform(0.0, 1.5)));
      if (rng.uniform(0, 10) == 0) p[rng.uniform(0, 3)] = odd[rng.uniform(0, 7)];
      f.at<cv::Vec3f>(y, x) = p;
    }
  return f;
}

void expect_definition(const cv::Mat& in, const cv::Mat& out, const ToneCurve& curve, const MesopicColour& m) {
  for (int y = 0; y < in.rows; ++y)
    for (int x = 0; x < in.cols; ++x) {
      const float rho = m.rho_map ? m.rho_map->at<float>(y, x) : m.rho;
      const cv::Vec3f want = defined(in.at<cv::Vec3f>(y, x), curve, m, rho), got = out.at<cv::Vec3f>(y, x);
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(std::memcmp(&want[c], &got[c], sizeof(float)), 0)
            << x << "," << y << " channel " << c << ": " << want[c] << " against " << got[c];
    }
}

TEST(ToneMapRows, PhotopicAndMesopicGiveTheDefinitionsBits) {
  const cv::Mat in = frame(cv::Size(257, 19));  // odd widths: the vector loops' tails
  for (const double adaptation_log : {-3.0, 0.0, 4.0}) {
    const ToneCurve curve(adaptation_log, ToneCurveParams{});
    cv::Mat out;
    tone_map(in, curve, out);
    MesopicColour photopic;
    photopic.scotopic_weights = cv::Vec3f(kPhotopicR, kPhotopicG, kPhotopicB);
    photopic.tint_ratio = cv::Vec3f(0, 0, 0);
    photopic.hue_shift = false;
    expect_definition(in, out, curve, photopic);

    MesopicColour m;
    m.rho = 0.35f;
    m.scotopic_weights = cv::Vec3f(-0.0772f, 0.5634f, 0.5138f);
    m.tint_ratio = cv::Vec3f(0.9f, 1.0f, 1.3f);
    for (const bool hue : {true, false}) {
      m.hue_shift = hue;
      m.rho_map = nullptr;
      tone_map(in, curve, m, out);
      expect_definition(in, out, curve, m);
      cv::Mat rho(in.size(), CV_32F);
      cv::randu(rho, 0.0, 1.0);
      m.rho_map = &rho;
      tone_map(in, curve, m, out);
      expect_definition(in, out, curve, m);
    }
  }
}

}  // namespace
}  // namespace eyestream::retina
