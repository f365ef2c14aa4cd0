#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/envs/sma_limb/open_loop_inputs.hpp"
#include "tendril/envs/sma_limb/throttle_sources.hpp"

namespace tendril::envs::sma_limb {

// How a data set is collected on SmaLimb/Robot-v0 (the thesis' exploration firmware; spec §2.2):
// each throttle pair is held for `hold_readings` readings; when a reading passes the 100°
// cut-off, the throttles are zero for `cutoff_cooldown_s` (the coils cool) before the source is
// asked again. Every reading is logged, cool-downs included.
struct CollectSettings {
  double duration_s = 600.0;
  int hold_readings = 10;
  double cutoff_cooldown_s = 20.0;
};

// One row per reading: the reading (time stamp, angles without zero offsets) and what drove the
// limb from it to the next reading — the throttles commanded and the PWM the firmware applied
// (zero during its cut-off). The row layout of the data-set files (docs/results/sma_limb.md).
struct LimbLog {
  std::vector<double> time_s;
  std::vector<Eigen::Vector2d> angles_deg;
  std::vector<Eigen::Vector2i> throttles;
  std::vector<std::array<int, 4>> pwm;
  int64_t cutoffs = 0;  // readings past the cut-off

  std::size_t size() const { return time_s.size(); }
  void add(double time, const Eigen::Vector2d& angles, const Eigen::Vector2i& throttle_pair,
           const std::array<int, 4>& coil_pwm) {
    time_s.push_back(time);
    angles_deg.push_back(angles);
    throttles.push_back(throttle_pair);
    pwm.push_back(coil_pwm);
  }
};

// Resets `env` (an SmaLimb/Robot-v0 or anything with its observation and info keys) with `seed`
// and drives it with `source` until the readings reach settings.duration_s. The source draws from
// its own stream, Rng(seed, 1). `on_reading`, when set, sees the robot time of every reading.
LimbLog collect(Env& env, ThrottleSource& source, const CollectSettings& settings, uint64_t seed,
                const std::function<void(double robot_time_s)>& on_reading = nullptr);

// Resets `env` with `seed` and sends `inputs` open loop, one row per reading, rounded to the
// robot's integer throttles (the firmware's own cut-off still applies; nothing reacts to the
// readings). Logs one row per input plus the reading after the last (throttles 0 there).
LimbLog drive_open_loop(Env& env, const ThrottleSequence& inputs, uint64_t seed);

}  // namespace tendril::envs::sma_limb
