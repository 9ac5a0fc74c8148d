#include "io/transfer_functions.hpp"

#include <algorithm>
#include <cmath>

namespace eyestream::io {

namespace {
// ST 2084 constants.
constexpr double kM1 = 2610.0 / 16384.0, kM2 = 2523.0 / 4096.0 * 128.0;
constexpr double kC1 = 3424.0 / 4096.0, kC2 = 2413.0 / 4096.0 * 32.0, kC3 = 2392.0 / 4096.0 * 32.0;
constexpr double kPqPeak = 10000.0;
// BT.2100 HLG constants.
constexpr double kA = 0.17883277, kB = 1.0 - 4.0 * kA, kC = 0.55991073;  // c = 0.5 - a ln(4a)
}  // namespace

double pq_to_luminance(double signal) {
  const double e = std::pow(std::clamp(signal, 0.0, 1.0), 1.0 / kM2);
  return kPqPeak * std::pow(std::max(e - kC1, 0.0) / (kC2 - kC3 * e), 1.0 / kM1);
}

double luminance_to_pq(double cd_m2) {
  const double y = std::pow(std::clamp(cd_m2 / kPqPeak, 0.0, 1.0), kM1);
  return std::pow((kC1 + kC2 * y) / (1.0 + kC3 * y), kM2);
}

double hlg_to_scene(double signal) {
  const double e = std::clamp(signal, 0.0, 1.0);
  return e <= 0.5 ? e * e / 3.0 : (std::exp((e - kC) / kA) + kB) / 12.0;
}

double scene_to_hlg(double scene) {
  const double e = std::clamp(scene, 0.0, 1.0);
  return e <= 1.0 / 12.0 ? std::sqrt(3.0 * e) : kA * std::log(12.0 * e - kB) + kC;
}

double hlg_system_gamma(double peak_cd_m2) { return 1.2 + 0.42 * std::log10(peak_cd_m2 / 1000.0); }

double bt1886_to_linear(double signal) { return std::pow(std::clamp(signal, 0.0, 1.0), 2.4); }

}  // namespace eyestream::io
