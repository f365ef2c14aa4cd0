#include "tendril/safety/search_space.hpp"

#include "tendril/core/error.hpp"
#include "tendril/envs/safety_task.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::safety {

std::unique_ptr<envs::SafetySearchSpace> search_space_of(Env& env) {
  if (const auto* task = envs::find_wrapper<envs::SafetyTask>(env)) {
    return task->safety_search_space();
  }
  throw Error(
      "the environment has no search space for the safety filter's tools (its task is no "
      "envs::SafetyTask; the safe-control environments and the limb's safety task are)",
      "safety::search_space_of");
}

}  // namespace tendril::safety
