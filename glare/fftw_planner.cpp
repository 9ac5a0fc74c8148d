#include "glare/fftw_planner.hpp"

namespace eyestream::glare {

std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace eyestream::glare
