#include "samples/chaos_fluctuation.hpp"

#include <cmath>

namespace eyestream::samples {

namespace {

// SplitMix64: a well-mixed 64-bit hash.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

constexpr double kEdge = 1e-9;

}  // namespace

ChaosFluctuation::ChaosFluctuation(std::uint64_t seed) : seed_(seed), s_(0.0) { s_ = restart(); }

double ChaosFluctuation::restart() {
  const double u = double(mix(seed_ * 0x100000001b3ULL + restarts_++) >> 11) / 9007199254740992.0;  // [0, 1)
  return 0.05 + 0.9 * u;
}

double ChaosFluctuation::next() {
  static const double u = std::pow(2.0, kZ - 1.0);
  s_ = s_ < 0.5 ? s_ + u * std::pow(s_, kZ) : s_ - u * std::pow(1.0 - s_, kZ);
  if (!(s_ > kEdge && s_ < 1.0 - kEdge)) s_ = restart();
  return s_;
}

}  // namespace eyestream::samples
