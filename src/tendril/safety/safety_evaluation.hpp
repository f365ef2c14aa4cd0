#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/safety/constraint.hpp"
#include "tendril/safety/safety_filter.hpp"

namespace tendril::safety {

// Returns and safety of `episodes` episodes (reset seeds seed, seed + 1, ...). An episode is
// safe when none of its observations, the first included, lies in X_unsafe (seed 001 §6.4.1's
// safety rate: the episode reaches its maximum length without a violation).
struct SafetyEvaluation {
  int episodes = 0;
  double mean_return = 0.0;
  double std_return = 0.0;
  double safety_rate = 0.0;        // fraction of safe episodes
  double intervention_rate = 0.0;  // of the filter's decisions (0 without a filter)
};
// With `trajectory`, every step is appended as a row [episode, t, x..., u..., unsafe(x')], x the
// observation acted on and u the action taken.
SafetyEvaluation evaluate_safety(Env& env, const envs::SafetyConstraint& constraint,
                                 const TaskActor& actor, int episodes, uint64_t seed,
                                 std::vector<std::vector<double>>* trajectory = nullptr);

// The task experiment of a training config, read as its command reads it: a co-training
// experiment (`safety:` section, SafetyExperiment) or a constrained baseline (`constrained:`,
// ConstrainedExperiment) for `tendril train`'s safety and constrained experiments, a plain
// experiment otherwise.
rl::Experiment task_experiment_of_config(const Config& config);

// The task experiment a run was trained with, from its config.yaml (a run of `tendril train` has
// its checksum checked).
rl::Experiment task_experiment_of_run(const std::filesystem::path& run_directory);

// Who acts in an evaluation of a run: its own task policy, the policy of another run on the
// same environment (a policy not co-trained with the critic, seed 001 Table 6.2), or uniformly
// random actions.
struct TaskSource {
  enum class Kind { kOwn, kRun, kRandom };
  Kind kind = Kind::kOwn;
  std::filesystem::path run;  // for kRun
};

// A run evaluated on the same episodes without and, when it has a safety.critic, with the filter
// at ε₂. Returns are the task reward's and the starts the task's: an environment's
// `unsafe_penalty` is set to 0 and its training aid `start_anywhere` to false for this.
struct RunSafetyEvaluation {
  double epsilon = 0.0;
  SafetyEvaluation unfiltered;
  std::optional<SafetyEvaluation> filtered;
};
// With `trajectory`, the steps of the filtered evaluation (of the unfiltered one for a run
// without a critic), as evaluate_safety records them.
RunSafetyEvaluation evaluate_safety_run(const std::filesystem::path& run_directory, double epsilon,
                                        int episodes, uint64_t seed, const TaskSource& task = {},
                                        std::vector<std::vector<double>>* trajectory = nullptr);

}  // namespace tendril::safety
