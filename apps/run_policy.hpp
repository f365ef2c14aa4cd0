#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::apps {

// A run's trained policy and an environment to run it on, as `eval` and `record` use them: the
// run's policy file (model.policy, or best_model.policy with `best`), which acts on the
// environment in the run's wrappers (rl::make_env); or, for a run without one (paused,
// interrupted), its newest checkpoint's policy on an environment with the run's frozen observation
// statistics. Raw rewards either way.
struct RunPolicy {
  rl::Experiment experiment;
  std::filesystem::path source;  // the policy file or checkpoint it came from
  std::unique_ptr<Env> env;
  std::shared_ptr<const rl::Policy> policy;
  std::shared_ptr<void> keep_alive;  // what the policy needs (a checkpoint's algorithm and env)
};

// `overrides` (key=value, as --set gives them) change the run's experiment for this, e.g. the
// environment's parameters to test a policy on conditions it was not trained on.
RunPolicy open_run_policy(const std::filesystem::path& run, bool best,
                          const std::vector<std::pair<std::string, std::string>>& overrides = {});

}  // namespace tendril::apps
