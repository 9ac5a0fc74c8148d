#include "retina/pow_table.hpp"

#include <map>
#include <memory>
#include <mutex>

namespace eyestream::retina {

PowTable::PowTable(double exponent) : exponent_(exponent), table_(size_t(kOctaves) * kSteps + 2) {
  for (size_t i = 0; i < table_.size(); ++i) {
    const double x = std::ldexp(1.0 + double(i % kSteps) / kSteps, int(i / kSteps) - kOctaves);
    table_[i] = float(std::pow(x, exponent));
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
