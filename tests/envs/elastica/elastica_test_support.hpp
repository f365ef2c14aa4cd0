#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/envs/elastica/elastica_arm_env.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs::elastica::testing {

// A registered Elastica case as the registry builds it (inside its TimeLimit), and the case
// itself for the test hooks. When the id does not build a `Case`, the calling test fails with an
// exception naming it (callers use `task` straight away, so it is never null).
template <typename Case = ElasticaArmEnv>
struct Made {
  std::unique_ptr<Env> env;
  Case* task = nullptr;
};

template <typename Case = ElasticaArmEnv>
Made<Case> make_case(const std::string& id, const std::string& params_yaml = "{}") {
  Made<Case> made;
  made.env = make(id, Config::parse(params_yaml));
  made.task = find_wrapper<Case>(*made.env);
  if (made.task == nullptr) {
    throw std::runtime_error(id + " does not build the expected Elastica case");
  }
  return made;
}

// The 11 sampled arm nodes, coordinate-major, as the observation holds them.
inline void expect_rod_block(const Observation& observation, const physics::Rod& rod) {
  const Eigen::Matrix3Xd nodes = rod.sampled_node_positions(11);
  for (int c = 0; c < 3; ++c) {
    for (int k = 0; k < 11; ++k) {
      ASSERT_EQ(observation[11 * c + k], static_cast<float>(nodes(c, k)))
          << "coordinate " << c << ", node " << k;
    }
  }
}

}  // namespace tendril::envs::elastica::testing
