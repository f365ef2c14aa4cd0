#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/env_description.hpp"

namespace tendril::envs {

// Identity-v0, Stable-Baselines3's IdentityEnv (stable_baselines3/common/envs/identity_env.py):
// the state is an index drawn uniformly from {0, …, n−1}, redrawn after every step; the reward is
// 1 when the action equals the state the agent was shown, else 0. A sanity check that an
// algorithm can learn the simplest possible mapping.
//
// Convention: the observation is the state one-hot encoded, in a Box(n, [0, 1]) — the input
// SB3's policies build from a Discrete observation — and the action is Discrete(n). The task
// never ends by itself; the registry adds SB3's 100-step episode limit.
class Identity : public Env {
 public:
  struct Params {
    int64_t n = 10;  // number of states and actions
  };
  // Registry factory; params: {n}.
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  Identity() : Identity(Params{}) {}
  explicit Identity(Params params);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  // The state, the random stream and the episode flags: exact snapshots.
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  int64_t state() const { return state_; }

 private:
  Observation observe() const;

  Space observation_space_;
  Space action_space_;
  Rng rng_;
  int64_t state_ = 0;
};

}  // namespace tendril::envs
