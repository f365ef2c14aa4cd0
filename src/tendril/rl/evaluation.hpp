#pragma once

#include <cstdint>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::rl {

struct EvaluationResult {
  std::vector<double> returns;  // undiscounted, one per episode
  std::vector<int64_t> lengths;
  double mean_return() const;
  double std_return() const;
};

// SB3's evaluate_policy: runs `episodes` full episodes of `env` (which must end them, e.g. by a
// time limit) with `policy`, the first reset seeded with `seed`; a stochastic policy draws
// from a stream derived from `seed` too.
EvaluationResult evaluate_policy(const Policy& policy, Env& env, int episodes, bool deterministic,
                                 uint64_t seed);

}  // namespace tendril::rl
