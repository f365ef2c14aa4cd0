#pragma once

#include <string>

#include "tendril/core/config.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::testing {

// What a registered environment cannot default, for tests that make every registered id: its
// registry entry's example_params (the SMA limb robot always names its calibration; `none` is
// its nominal table on raw readings). tests/python/conftest.py's REQUIRED_PARAMS says the same.
inline Config required_env_params(const std::string& id) {
  const std::string& example = envs::builtin_registry().spec(id).example_params;
  return example.empty() ? Config() : Config::parse(example);
}

}  // namespace tendril::testing
