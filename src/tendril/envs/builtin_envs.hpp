#pragma once

#include "tendril/envs/registry.hpp"

namespace tendril::envs {

// Adds every environment tendril ships to `registry`. A new environment is one `registry.add`
// line in builtin_envs.cpp; a family of them (e.g. the physics-based tasks) may instead add one
// call to its own `register_<family>_envs(registry)` there.
void register_builtin_envs(Registry& registry);

}  // namespace tendril::envs
