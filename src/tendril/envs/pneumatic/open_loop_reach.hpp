#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/envs/pneumatic/arm_dynamics.hpp"

namespace tendril::envs::pneumatic {

// How far the twin's stochastic behaviours alone carry an open-loop plan from its goal: the
// lower bound of the training-to-reality gap of seed 002's Fig. 7 (open-loop testing), that a
// perfect model of the arm would leave.
//
// For each goal, static pressures p* that bring module 3's tip to it are searched on the "model"
// — the same twin instance (its imbalance included, which a model learned from its data would
// know) with drift, hysteresis, the elasticity of the day and sensor noise off — by a seeded random search in [0, 1.5]⁹.
// The plan ramps the commands from 0 to p* at the 0.15 bar/step rate limit and holds them to the
// end of a 150-step episode. It is replayed in `trials` trials on the full twin of every
// scenario (first trial begun with the seed, the others without); the final distance of
// module 3's tip from the goal is recorded. The plate is left out: this measures the arm, not
// the task.
struct OpenLoopReport {
  struct Goal {
    std::string name;
    Eigen::Vector3d position;     // mm
    ChamberVector pressures;      // p*, bar
    double model_distance = 0.0;  // the model's final distance under the plan, mm
  };
  struct Row {
    std::string scenario, goal;
    int trial = 0;  // from 1
    double final_distance_mm = 0.0;
  };
  std::vector<Goal> goals;
  std::vector<Row> rows;
  double wall_seconds = 0.0;
};

// The `open_loop` mapping of a replay experiment, all optional:
//   open_loop: {goals: [main, G1, G2, G3], trials: 17, search_evaluations: 600, seed: 0}
// (17 trials as in Fig. 7). Raises Error naming a bad key or value.
struct OpenLoopOptions {
  std::vector<std::string> goals{"main", "G1", "G2", "G3"};
  int trials = 17;
  int search_evaluations = 600;
  uint64_t seed = 0;
};
OpenLoopOptions open_loop_options(const Config& open_loop);

// Runs the analysis on the twin built from `robot_params` (PneumaticArm/Robot-v0's) for each of
// `scenarios`.
OpenLoopReport open_loop_reach(const Config& robot_params,
                               const std::vector<std::string>& scenarios,
                               const OpenLoopOptions& options);

// Writes <directory>/open_loop_reach.csv (scenario,goal,trial,final_distance_mm) after '#'
// lines naming `invocation` and each goal's p* and model distance. Raises Error, writing
// nothing, if the file exists.
void write_open_loop_report(const OpenLoopReport& report, const std::filesystem::path& directory,
                            const std::string& invocation);

}  // namespace tendril::envs::pneumatic
