#pragma once

#include <memory>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/env_description.hpp"

namespace tendril::envs {

// IdentityBox-v0, Stable-Baselines3's IdentityEnvBox: the state s ~ U(−1, 1) is shown as the
// observation, Box(1, [−1, 1]); the reward is 1 when the action a satisfies s − eps ≤ a ≤ s + eps,
// else 0; s is redrawn after every step. The task never ends by itself; the registry adds SB3's
// 100-step episode limit.
class IdentityBox : public Env {
 public:
  struct Params {
    double eps = 0.05;  // half-width of the rewarded interval around the state
  };
  // Registry factory; params: {eps}.
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  IdentityBox() : IdentityBox(Params{}) {}
  explicit IdentityBox(Params params);

  const Space& observation_space() const override { return space_; }
  const Space& action_space() const override { return space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  // The state, the random stream and the episode flags: exact snapshots.
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  float state() const { return state_; }

 private:
  Space space_;
  float eps_;
  Rng rng_;
  float state_ = 0.0f;
};

}  // namespace tendril::envs
