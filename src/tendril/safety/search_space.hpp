#pragma once

#include <memory>

#include "tendril/core/env.hpp"
#include "tendril/envs/safety_search_space.hpp"

namespace tendril::safety {

// The search space of an environment whose task is a SafetyTask (envs/safety_task.hpp), found
// through any wrappers: the double integrator's (x, ẋ) over (2 m, 3 m/s), the Dubins car's
// (x, y, ψ) over (2 m, 2 m, π rad) with the default geometry, the limb safety task's (θx, θy,
// θ̇x, θ̇y) over its safe radius (30° and 30 °/s). Raises Error for other environments.
std::unique_ptr<envs::SafetySearchSpace> search_space_of(Env& env);

}  // namespace tendril::safety
