#pragma once

#include "tendril/envs/registry.hpp"

namespace tendril::envs::tendon_arm {

// Adds the tendon arm's environments to `registry`: TendonArm/Robot-v0, TendonArm/Reach-v0 and
// TendonArm/LearnedReach-v0 (register_builtin_envs calls it).
void register_envs(Registry& registry);

}  // namespace tendril::envs::tendon_arm
