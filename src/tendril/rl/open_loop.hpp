#pragma once

#include <cstdint>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/core/policy.hpp"
#include "tendril/envs/runner/policy_runner.hpp"

namespace tendril::rl {

// Open-loop evaluation (seed 002 §V-B, Fig. 7: "replaying the model-env action sequence" on the
// robot): `actions` — e.g. recorded_actions of a policy in the environment it was trained in —
// applied in order to `env` in each of `episodes` episodes, whatever `env` observes. Episode k
// resets with seed + k (the policy runner's rule); it ends when `env` ends it or the actions run
// out.
envs::RunResult replay_actions(const std::vector<Action>& actions, Env& env, int episodes,
                               uint64_t seed);
// The actions `policy` takes in one episode of `env` reset with `seed`: the runner's episode 0.
std::vector<Action> recorded_actions(const tendril::Policy& policy, Env& env, bool deterministic,
                                     uint64_t seed);

}  // namespace tendril::rl
