#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/rl/algorithm.hpp"

namespace tendril::rl {

// How to build one algorithm from an experiment's `algo` mapping (the RL Zoo's ALGOS table,
// the counterpart of the environment registry).
struct AlgorithmSpec {
  std::string name;  // as experiments name it: "ppo"
  std::string summary;
  // Reads and checks the configuration (preset, keys, ranges; Error naming the key) and returns
  // its discount γ, which reward normalization needs before the algorithm exists.
  std::function<double(const Config& algo)> gamma;
  std::function<std::unique_ptr<Algorithm>(envs::VecEnv& env, const Config& algo, uint64_t seed)>
      factory;
};

// Every algorithm tendril ships, in a fixed order.
const std::vector<AlgorithmSpec>& registered_algorithms();
// Raises Error naming `where` and listing the known names when `name` is unknown.
const AlgorithmSpec& algorithm_spec(std::string_view name, const std::string& where);

}  // namespace tendril::rl
