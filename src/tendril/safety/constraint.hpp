#pragma once

#include <memory>

#include "tendril/core/env.hpp"
#include "tendril/envs/safety_constraint.hpp"

namespace tendril::safety {

// The constraint of an environment whose task is a SafetyTask (envs/safety_task.hpp), found
// through any wrappers: raises Error for an environment without one.
std::unique_ptr<envs::SafetyConstraint> constraint_of(Env& env);

}  // namespace tendril::safety
