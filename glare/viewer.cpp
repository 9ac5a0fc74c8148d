#include "glare/viewer.hpp"

#include <cmath>

namespace eyestream::glare {

double pupil_diameter_mm(double log_l) { return 4.9 - 3.0 * std::tanh(0.4 * (log_l + 1.0)); }

}  // namespace eyestream::glare
