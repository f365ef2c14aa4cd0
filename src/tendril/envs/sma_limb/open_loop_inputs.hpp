#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

namespace tendril::envs::sma_limb {

// Throttle pairs (x, y), one row per step.
using ThrottleSequence = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;

// Seed 001's open-loop test inputs (thesis Fig. 4.4; [CODE] hardware_exp trajectories: 800 steps
// each, published at 20 Hz ⇒ 40 s), as two throttles (x, y), scaled by `amplitude` (10: full
// throttle), for step k = 0 … steps − 1 with period P = 800:
//   sine      (sin 2πk/P, cos 2πk/P)              one circle per period
//   square    (+1, +1), (+1, −1), (−1, −1), (−1, +1) for P/4 steps each
//   sawtooth  x ramps from −1 by 2/P per step and wraps; y a quarter period ahead
// The same inputs drive a learned model (dynamics/open_loop) and the robot (drive_open_loop).
ThrottleSequence open_loop_inputs(const std::string& kind, int64_t steps, double amplitude = 10.0,
                                  int64_t period = 800);

}  // namespace tendril::envs::sma_limb
