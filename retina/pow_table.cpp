#include "retina/pow_table.hpp"

#include <map>
#include <memory>
#include <mutex>

#include "retina/vector_clones.hpp"

namespace eyestream::retina {

PowTable::PowTable(double exponent) : exponent_(exponent), entries_(size_t(kOctaves) * kSteps + 1) {
  // Points up to x = 1 (the last entry's own point, read with a zero fraction) and one beyond.
  std::vector<float> points(entries_.size() + 1);
  for (size_t i = 0; i < points.size(); ++i) {
    const double x = std::ldexp(1.0 + double(i % kSteps) / kSteps, int(i / kSteps) - kOctaves);
    points[i] = float(std::pow(x, exponent));
  }
  for (size_t i = 0; i < entries_.size(); ++i) entries_[i] = entry(points[i], points[i + 1] - points[i]);
}

std::uint64_t PowTable::entry(float at, float step) {
  std::uint32_t lo, hi;
  std::memcpy(&lo, &at, sizeof lo);
  std::memcpy(&hi, &step, sizeof hi);
  return lo | std::uint64_t(hi) << 32;
}

EYESTREAM_VECTOR_CLONES
void PowTable::batch(const float* __restrict x, float* __restrict y, int n) const {
  const std::uint64_t* __restrict t = entries_.data();
  int below = 0;  // values under the table's least octave, other than 0
  for (int i = 0; i < n; ++i) {
    std::uint32_t bits;
    std::memcpy(&bits, &x[i], sizeof bits);
    bits &= 0x7fffffffu;  // -0 as 0
    const int octave = int(bits >> 23) - 127 + kOctaves;
    const int under = octave < 0;
    const int at = octave * (1 - under) * kSteps + int((bits >> 13) & (kSteps - 1));
    const float f = float(int(bits & 8191u)) * (1.0f / 8192.0f);
    float point, step;
    split(t[at], point, step);
    const float v = point + f * step;
    y[i] = v * float(1 - under);  // (v is finite: 0 under the table)
    below |= under & int(bits != 0);
  }
  if (below) {  // rare: std::pow, as operator() takes it
    const float least = std::ldexp(1.0f, -kOctaves);
    for (int i = 0; i < n; ++i)
      if (x[i] > 0.0f && x[i] < least) y[i] = (*this)(x[i]);
  }
}

const PowTable& shared_pow_table(double exponent) {
  static std::mutex m;
  static auto* tables = new std::map<double, std::unique_ptr<PowTable>>;  // never destroyed
  std::lock_guard<std::mutex> lock(m);
  std::unique_ptr<PowTable>& t = (*tables)[exponent];
  if (!t) t = std::make_unique<PowTable>(exponent);
  return *t;
}

}  // namespace eyestream::retina
