#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::rl {

struct EvaluationResult {
  std::vector<double> returns;  // undiscounted, one per episode
  std::vector<int64_t> lengths;
  std::vector<Info> final_infos;  // each episode's last step's info (success, distances, …)
  double mean_return() const;
  double std_return() const;
  // The fraction of episodes whose last info reports is_success > 0.5; none when no episode's
  // last info has is_success.
  std::optional<double> success_rate() const;
};

// SB3's evaluate_policy: runs `episodes` full episodes of `env` (which must end them, e.g. by a
// time limit) with `policy`, the first reset seeded with `seed`; a stochastic policy draws
// from a stream derived from `seed` too.
EvaluationResult evaluate_policy(const Policy& policy, Env& env, int episodes, bool deterministic,
                                 uint64_t seed);

// The same over the N environments of a vector env stepped together (one batched policy call and,
// for a batched env, one model call per step): env i runs (episodes + i) / N whole episodes (as
// SB3's evaluate_policy on a VecEnv, so that short episodes are not favoured); the envs are reset
// with `seed`, a stochastic policy draws from a stream derived from it. Results are ordered by
// env, then episode. Rewards are the vector env's (raw unless it normalizes them).
EvaluationResult evaluate_policy(const Policy& policy, envs::VecEnv& env, int episodes,
                                 bool deterministic, uint64_t seed);

// Open-loop evaluation (seed 002 §V-B, Fig. 7: "replaying the model-env action sequence" on the
// robot): `actions` — e.g. recorded_actions of a policy in the environment it was trained in —
// applied in order to `env` in each of `episodes` episodes (reset seeds `seed`, then unseeded),
// whatever `env` observes. An episode ends when `env` ends it or the actions run out.
EvaluationResult replay_actions(const std::vector<Action>& actions, Env& env, int episodes,
                                uint64_t seed);
// The actions `policy` takes in one episode of `env` (reset with `seed`).
std::vector<Action> recorded_actions(const Policy& policy, Env& env, bool deterministic,
                                     uint64_t seed);

}  // namespace tendril::rl
