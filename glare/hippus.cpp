#include "glare/hippus.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

namespace eyestream::glare {

namespace {
constexpr int kLines = 200;

double factor(double p) {
  p = std::clamp(p, 0.5, Hippus::kMaxPupil_mm);
  return Hippus::kMaxPupil_mm / p * std::sqrt(1.0 - p / Hippus::kMaxPupil_mm);
}
}  // namespace

Hippus::Hippus(std::int64_t seed) {
  cv::RNG rng(0x41990000ULL ^ std::uint64_t(seed) * 0xbf58476d1ce4e5b9ULL);
  for (int i = 0; i < kLines; ++i) {
    // Log-spaced, each jittered within its step (no common period).
    const double u = (i + rng.uniform(0.0, 1.0)) / kLines;
    hz_.push_back(kLowHz * std::pow(kHighHz / kLowHz, u));
    phase_.push_back(rng.uniform(0.0, 2.0 * M_PI));
  }
}

double Hippus::noise(double t) const {
  double sum = 0.0;
  for (size_t i = 0; i < hz_.size(); ++i) sum += std::sin(2.0 * M_PI * hz_[i] * t + phase_[i]);
  return sum * std::sqrt(2.0 / double(hz_.size()));  // each sinusoid's RMS is 1/sqrt(2)
}

double Hippus::rms_mm(double pupil_mm) { return kRmsAt4mm_mm * factor(pupil_mm) / factor(4.0); }

double Hippus::offset_mm(double pupil_mm, double t) const { return rms_mm(pupil_mm) * noise(t); }

}  // namespace eyestream::glare
