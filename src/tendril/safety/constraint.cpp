#include "tendril/safety/constraint.hpp"

#include "tendril/core/error.hpp"
#include "tendril/envs/safety_task.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::safety {

std::unique_ptr<envs::SafetyConstraint> constraint_of(Env& env) {
  if (const auto* task = envs::find_wrapper<envs::SafetyTask>(env)) {
    return task->safety_constraint();
  }
  throw Error(
      "the environment has no safety constraint (its task is no envs::SafetyTask; the "
      "safe-control environments and the limb's safety task are)",
      "safety::constraint_of");
}

}  // namespace tendril::safety
