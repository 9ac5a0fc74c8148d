#include "samples/fixed_gaze.hpp"

namespace eyestream::samples {

std::vector<io::GazeSample> fixed_gaze(double x, double y, double duration_s, double rate_hz) {
  std::vector<io::GazeSample> out;
  for (int i = 0; i < int(duration_s * rate_hz); ++i) out.push_back({i / rate_hz, x, y, io::EyeState::kOpen});
  return out;
}

}  // namespace eyestream::samples
