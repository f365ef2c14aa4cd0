#pragma once

#include <cstdint>

#include "tendril/core/env.hpp"
#include "tendril/core/policy.hpp"
#include "tendril/envs/runner/policy_runner.hpp"

namespace tendril::testing {

// `episodes` whole episodes of the deterministic policy, episode k reset with seed + k.
inline envs::RunResult evaluate(const Policy& policy, Env& env, int64_t episodes, uint64_t seed) {
  envs::RunSettings settings;
  settings.episodes = episodes;
  settings.seed = seed;
  return envs::run_policy(policy, env, settings);
}

}  // namespace tendril::testing
