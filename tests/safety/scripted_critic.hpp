#pragma once

#include "tendril/safety/safety_critic.hpp"

namespace tendril::safety::testing {

// Q_s(x, u) = x₀ − u₀ with safe action −1: a critic whose values are known by hand.
class ScriptedCritic : public SafetyCritic {
 public:
  double value(const Observation& x, const Action& u) const override { return x[0] - u[0]; }
  Action safe_action(const Observation&) const override { return Action::Constant(1, -1.0f); }
};

}  // namespace tendril::safety::testing
