#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "tendril/core/config.hpp"

namespace tendril::envs::pneumatic {

// Seed 002's stochasticity analysis (§III-B, Fig. 2: "a random trajectory in the actuation space
// … ten trials with the same actuation space trajectory … distances of the following trials were
// computed with respect to the base trial") and its gap across the damage scenarios (Fig. 6: the
// mean absolute distance (MAD) of each module's tip from a reference under the same trajectory,
// for S0–S4), on any robot with PneumaticArm/Robot-v0's interface and `scenario` parameter.
//
// The trajectory is the data protocol's saturating signal from `seed`. For every scenario a robot
// is built from the same parameters (so the same instance), its first trial begun with `seed` and
// the others without (so the resting drift walks on between trials, as on the real arm). The
// reference is, as in Fig. 6, the learned model run open loop on the same commands from the
// arm's rest (`reference_model`); without one, the first trial of the first scenario listed
// (S0's base trial) stands in, so the S0 rows measure the trial-to-trial stochasticity alone and
// the S1–S4 rows damage on top of it.
struct ReplayReport {
  struct Row {
    std::string scenario;
    int trial = 0;                       // from 1
    int module = 0;                      // from 1
    double mad_from_reference_mm = 0.0;  // mean over time of |x − x_reference|
    double mad_from_own_base_mm = 0.0;   // of |x − x_(this scenario's trial 1)|
  };
  std::vector<Row> rows;
  // Mean over trials of module 3's distance from the reference at each step, one column per
  // scenario (steps × scenarios).
  std::vector<std::string> scenarios;
  Eigen::MatrixXd module_3_gap_mm;
  double period = 0.1;  // s per step
  double wall_seconds = 0.0;
};

// From an experiment file:
//   robot: {id: PneumaticArm/Robot-v0, params: {...}}   # `scenario` is set per scenario
//   scenarios: [S0, S1, S2, S3, S4]
//   trials: 10
//   duration_s: 30
//   seed: 0
//   signal: {...}                                     # as the data protocol's
//   reference_model: {model: FILE_OR_RUN, rest_from: DATA_FILE}   # optional, see above
// Raises Error naming a bad key or value.
ReplayReport replay_trials(const Config& config);

// Writes <directory>/replay_gap.csv (scenario,trial,module,mad_from_reference_mm,
// mad_from_own_base_mm) and <directory>/replay_gap_series.csv (time_s, then one column
// module3_gap_<scenario>_mm per scenario), each after a '#' line naming `invocation`. Raises
// Error, writing nothing, if either file exists.
void write_replay_report(const ReplayReport& report, const std::filesystem::path& directory,
                         const std::string& invocation);

}  // namespace tendril::envs::pneumatic
