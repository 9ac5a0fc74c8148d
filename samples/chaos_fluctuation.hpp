// "1/f" fluctuation from intermittent chaos, as Matsuda and Ikedo drive
// sunlight through swaying leaves (their eqs. 9-11): each light i's
// intensity is I / n * S_i(t), S_i an independent orbit of the map
//
//   S' = S + u S^z          for S < 1/2
//   S' = S - u (1 - S)^z    for S >= 1/2,     u = 2^(z - 1), 1 < z < 2,
//
// which carries [0, 1/2) and [1/2, 1) each onto [0, 1). Its marginal fixed
// points at 0 and 1 hold the orbit in long laminar stretches between
// bursts, which is what makes the spectrum fall as 1/f. With z = 1.55
// (the paper leaves z open between 1 and 2) the power spectrum of an orbit
// falls with a log-log slope of -1.0 to -1.1 from 1/256 to 1/8 cycles per
// step (tests/dappled_sunlight_test.cpp). An orbit that reaches 0 or 1 in
// floating point (where it would stay) restarts at a hashed point of
// (0.05, 0.95): the sequence is a pure function of the seed.
#pragma once

#include <cstdint>

namespace eyestream::samples {

class ChaosFluctuation {
 public:
  static constexpr double kZ = 1.55;
  explicit ChaosFluctuation(std::uint64_t seed);
  // The next value, in (0, 1).
  double next();
  double value() const { return s_; }

 private:
  std::uint64_t seed_, restarts_ = 0;
  double s_;
  double restart();
};

}  // namespace eyestream::samples
