#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>

#include "tendril/core/rng.hpp"
#include "tendril/rl/replay_buffer.hpp"

namespace tendril::testing {

// A full replay buffer of `size` random transitions, saved to `file`: observations and next
// observations ~ N(0, 1), actions ~ U(−1, 1), rewards 0.1·N(0, 1) (small beside the critics'
// spread, so that which critic a target takes matters), a quarter terminated.
inline void write_random_replay_buffer(const std::filesystem::path& file, int64_t size,
                                       int64_t observations, int64_t actions, uint64_t seed) {
  rl::ReplayBuffer buffer(size, observations, actions);
  Rng rng(seed);
  for (int64_t i = 0; i < size; ++i) {
    Eigen::VectorXf observation(observations), next(observations), action(actions);
    for (auto& x : observation) x = static_cast<float>(rng.normal());
    for (auto& x : next) x = static_cast<float>(rng.normal());
    for (auto& x : action) x = static_cast<float>(rng.uniform(-1.0, 1.0));
    buffer.add(observation, action, static_cast<float>(0.1 * rng.normal()), next,
               rng.uniform() < 0.25);
  }
  buffer.save(file);
}

}  // namespace tendril::testing
