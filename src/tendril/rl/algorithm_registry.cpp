#include "tendril/rl/algorithm_registry.hpp"

#include "tendril/core/error.hpp"
#include "tendril/rl/dqn/dqn.hpp"
#include "tendril/rl/ppo/ppo.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/td3/td3.hpp"
#include "tendril/rl/trpo/trpo.hpp"

namespace tendril::rl {

namespace {

// An entry for an algorithm whose config type reads itself with `read(algo)`.
template <typename AlgorithmType, typename Read>
AlgorithmSpec entry(std::string name, std::string summary, Read read) {
  return {
      std::move(name), std::move(summary),
      [read](const Config& algo) { return read(algo).common.gamma; },
      [read](envs::VecEnv& env, const Config& algo, uint64_t seed) -> std::unique_ptr<Algorithm> {
        return std::make_unique<AlgorithmType>(env, read(algo), seed);
      }};
}

}  // namespace

const std::vector<AlgorithmSpec>& registered_algorithms() {
  static const std::vector<AlgorithmSpec> algorithms{
      entry<Ppo>("ppo", "Proximal Policy Optimization (clipped surrogate)",
                 [](const Config& algo) { return PpoConfig::from_config(algo); }),
      entry<Trpo>("trpo", "Trust Region Policy Optimization",
                  [](const Config& algo) { return TrpoConfig::from_config(algo); }),
      entry<Sac>("sac", "Soft Actor-Critic",
                 [](const Config& algo) { return SacConfig::from_config(algo); }),
      entry<Td3>("td3", "Twin Delayed DDPG",
                 [](const Config& algo) { return Td3Config::from_config(algo, Td3Variant::kTd3); }),
      AlgorithmSpec{
          "ddpg", "Deep Deterministic Policy Gradient",
          [](const Config& algo) {
            return Td3Config::from_config(algo, Td3Variant::kDdpg).common.gamma;
          },
          [](envs::VecEnv& env, const Config& algo, uint64_t seed) -> std::unique_ptr<Algorithm> {
            return std::make_unique<Td3>(env, Td3Config::from_config(algo, Td3Variant::kDdpg), seed,
                                         Td3Variant::kDdpg);
          }},
      entry<Dqn>("dqn", "Deep Q-Network",
                 [](const Config& algo) { return DqnConfig::from_config(algo); }),
  };
  return algorithms;
}

const AlgorithmSpec& algorithm_spec(std::string_view name, const std::string& where) {
  std::string known;
  for (const AlgorithmSpec& spec : registered_algorithms()) {
    if (spec.name == name) return spec;
    known += (known.empty() ? "" : ", ") + spec.name;
  }
  throw Error("unknown algorithm '" + std::string(name) + "' (known: " + known + ")", where);
}

}  // namespace tendril::rl
