#include "tendril/envs/wrappers/rescale_action.hpp"

namespace tendril::envs {

RescaleAction::RescaleAction(std::unique_ptr<Env> inner)
    : Wrapper(std::move(inner)),
      action_space_(Space::box(inner_->action_space().size(), -1.0f, 1.0f)) {
  const Space& inner_space = inner_->action_space();
  require(inner_space.is_box() && inner_space.bounded(),
          "needs a Box action space with finite bounds, got " + inner_space.describe(),
          "envs::RescaleAction");
}

Action RescaleAction::to_inner(const Action& action) const {
  const Eigen::ArrayXf low = inner_->action_space().low().array();
  const Eigen::ArrayXf high = inner_->action_space().high().array();
  const Eigen::ArrayXf unit = action.array().max(-1.0f).min(1.0f);
  // Rounding can put low + (high − low) a hair past `high`; the final clamp keeps it inside.
  return (low + 0.5f * (unit + 1.0f) * (high - low)).max(low).min(high).matrix();
}

Step RescaleAction::step(const Action& action) {
  check_action(action_space_, action, "envs::RescaleAction");
  return inner_->step(to_inner(action));
}

}  // namespace tendril::envs
