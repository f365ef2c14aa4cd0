#pragma once

#include <memory>

#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs {

// The agent acts in [−1, 1]^n; actions are clipped to that cube and mapped affinely onto the
// inner Box bounds, a ↦ low + (a + 1)(high − low)/2 (Stable-Baselines3's unscale_action), so −1
// gives `low` and 1 gives `high`. The inner action space must be a Box with finite bounds.
class RescaleAction : public Wrapper {
 public:
  explicit RescaleAction(std::unique_ptr<Env> inner);

  const Space& action_space() const override { return action_space_; }
  Step step(const Action& action) override;

  // The inner action that `action` (in [−1, 1]^n) maps to.
  Action to_inner(const Action& action) const;

 private:
  Space action_space_;
};

}  // namespace tendril::envs
