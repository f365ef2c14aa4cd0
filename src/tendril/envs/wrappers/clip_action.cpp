#include "tendril/envs/wrappers/clip_action.hpp"

namespace tendril::envs {

ClipAction::ClipAction(std::unique_ptr<Env> inner) : Wrapper(std::move(inner)) {
  require(inner_->action_space().is_box(),
          "needs a Box action space, got " + inner_->action_space().describe(), "envs::ClipAction");
}

Step ClipAction::step(const Action& action) {
  const Space& space = inner_->action_space();
  check_action(space, action, "envs::ClipAction");
  return inner_->step(action.cwiseMax(space.low()).cwiseMin(space.high()));
}

}  // namespace tendril::envs
