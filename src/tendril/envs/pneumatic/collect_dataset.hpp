#pragma once

#include <filesystem>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/envs/pneumatic/pneumatic_dataset.hpp"
#include "tendril/envs/pneumatic/saturating_signal.hpp"

namespace tendril::envs::pneumatic {

// Records `rows` rows from a robot with PneumaticArm/Robot-v0's interface driven by `signal`,
// one row per control period (PneumaticDataset's row convention): the robot is reset with
// `seed`, then each row holds the observation, and the command then sent and held for one step.
// The observation's first 9 values are the tips (mm); with 18, the last 9 are the pressures.
// Raises Error if the robot ends the recording early (a non-finite state).
PneumaticDataset record_pneumatic_dataset(Env& robot, SaturatingSignal& signal, int rows,
                                          double period, uint64_t seed);

// The data protocol of seed 002 §III-C from an experiment file:
//
//   robot:
//     id: PneumaticArm/Robot-v0     # any environment with its interface
//     params: {scenario: S0, ...}   # its parameters; observe_pressures defaults to true here
//   duration_s: 600                 # 10 min: 6000 rows at the robot's control_period_s (0.1 s)
//   seed: 0                         # the robot's trial seed and the signal's stream
//   signal: {ceiling_min_bar: 0.5, ceiling_max_bar: 1.5, ceiling_hold_s: [5, 20],
//            hold_s: [0.5, 3], saturation_probability: 0.3}
//   output: data/pneumatic_arm/twin_s0.csv
//
// Writes the data set to `output` (or the file's `output`) with the resolved configuration and
// `invocation` (the command line) as metadata. Raises Error, writing nothing, on a bad key or
// value, or if the output file exists.
struct CollectionReport {
  std::filesystem::path file;
  int rows = 0;
  double wall_seconds = 0.0;
  PneumaticDataset data;
};
CollectionReport collect_pneumatic_dataset(const Config& config,
                                           const std::filesystem::path& output,
                                           const std::string& invocation);

}  // namespace tendril::envs::pneumatic
